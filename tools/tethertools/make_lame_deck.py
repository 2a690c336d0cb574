#!/usr/bin/env python3
"""Writes an ABAQUS/CalculiX deck of the Lame thick cylinder under internal pressure.

Plane elements (CPE*/CPS*): a quarter ring in the x-y plane with symmetry
conditions on both straight edges. Axisymmetric elements (CAX*): a slice
r in [a, b], z in [0, h] with u_z = 0 top and bottom (plane strain in z).

Exact plane-strain solution (CPE* and CAX*; used by the demo and the tests):
  u_r(r) = (1+nu) p a^2 / (E (b^2-a^2)) * ((1-2 nu) r + b^2 / r)
  sigma_rr = p a^2/(b^2-a^2) (1 - b^2/r^2), sigma_tt = p a^2/(b^2-a^2) (1 + b^2/r^2)
Plane stress (CPS*, a thin disc; same stresses, sigma_zz = 0):
  u_r(r) = (1/E) ((1-nu) C r + (1+nu) D / r),  C = p a^2/(b^2-a^2), D = p a^2 b^2/(b^2-a^2)

Usage: make_lame_deck.py OUT.inp [--type CPE8] [--nr 8] [--nt 16] [--nlgeom] [--print-all]
  --print-all  also print U of every node (NALL) and RF of every node of BOTTOM and
               TOP (used by tools/ccx_reference.py to compare with CalculiX)
For CAX* --nt counts elements along z over the height H: keep it small (e.g. 2)
so the elements are not long and thin.
"""
import argparse
import math

A, B, P, E, NU, H = 10.0, 20.0, 100.0, 200000.0, 0.3, 2.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--type", default="CPE8")
    ap.add_argument("--nr", type=int, default=8, help="elements through the wall")
    ap.add_argument("--nt", type=int, default=16, help="elements around the quarter (or along z for CAX)")
    ap.add_argument("--nlgeom", action="store_true")
    ap.add_argument("--print-all", action="store_true", help="also print U of all nodes and RF of BOTTOM and TOP nodes")
    args = ap.parse_args()
    etype = args.type.upper()
    quadratic = etype[-1] in "68" or etype.endswith("8R")
    tri = etype[3] in "36" if len(etype) > 3 else False
    axi = etype.startswith("CAX")
    nr, nt = args.nr, args.nt
    m = 2 if quadratic else 1
    ids = {}

    def position(i, j):
        r = A + (B - A) * i / (m * nr)
        if axi:
            return r, H * j / (m * nt)
        t = 0.5 * math.pi * j / (m * nt)
        return r * math.cos(t), r * math.sin(t)

    def node(i, j):
        if (i, j) not in ids:
            ids[(i, j)] = len(ids) + 1
        return ids[(i, j)]

    elements = []
    for i in range(nr):
        for j in range(nt):
            i0, j0 = m * i, m * j
            c = [(i0, j0), (i0 + m, j0), (i0 + m, j0 + m), (i0, j0 + m)]
            if not tri:
                conn = c[:]
                if quadratic:
                    conn += [(i0 + 1, j0), (i0 + 2, j0 + 1), (i0 + 1, j0 + 2), (i0, j0 + 1)]
                elements.append((conn, j == 0 and False, i == 0))
            else:
                t1 = [c[0], c[1], c[2]]
                t2 = [c[0], c[2], c[3]]
                if quadratic:
                    t1 += [(i0 + 1, j0), (i0 + 2, j0 + 1), (i0 + 1, j0 + 1)]
                    t2 += [(i0 + 1, j0 + 1), (i0 + 1, j0 + 2), (i0, j0 + 1)]
                elements.append((t1, False, False))
                elements.append((t2, False, i == 0))
    lines = ["*HEADING", f"Lame thick cylinder a={A} b={B} p={P} ({etype}, {nr}x{nt})"]
    conns = [[node(*ij) for ij in conn] for conn, _, _ in elements]
    lines.append("*NODE, NSET=NALL")
    for (i, j), n in sorted(ids.items(), key=lambda kv: kv[1]):
        x, y = position(i, j)
        lines.append(f"{n}, {x:.15g}, {y:.15g}")
    lines.append(f"*ELEMENT, TYPE={etype}, ELSET=EALL")
    for k, conn in enumerate(conns, 1):
        lines.append(f"{k}, " + ", ".join(map(str, conn)))
    jmax = m * nt
    inner = sorted(n for (i, j), n in ids.items() if i == 0)
    outer = sorted(n for (i, j), n in ids.items() if i == m * nr)
    bottom = sorted(n for (i, j), n in ids.items() if j == 0)
    top = sorted(n for (i, j), n in ids.items() if j == jmax)

    def nset(name, members):
        lines.append(f"*NSET, NSET={name}")
        for k in range(0, len(members), 16):
            lines.append(", ".join(map(str, members[k:k + 16])))

    nset("INNER", inner)
    nset("OUTER", outer)
    nset("BOTTOM", bottom)
    nset("TOP", top)
    # the inner face: the edge from the last corner back to the first (S3 for triangles, S4 for quads)
    face = "S3" if tri else "S4"
    lines.append("*SURFACE, NAME=BORE, TYPE=ELEMENT")
    for k, (conn, _, on_inner) in enumerate(elements, 1):
        if on_inner:
            lines.append(f"{k}, {face}")
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL", "1.",
              "*BOUNDARY", "BOTTOM, 2, 2"]
    lines.append("TOP, 2, 2" if axi else "TOP, 1, 1")
    lines += [f"*STEP{', NLGEOM' if args.nlgeom else ''}", "*STATIC", "1., 1.",
              "*DSLOAD", f"BORE, P, {P:g}",
              "*NODE PRINT, NSET=INNER", "U",
              "*NODE PRINT, NSET=OUTER", "U",
              "*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY", "RF",
              "*EL PRINT, ELSET=EALL", "S"]
    if args.print_all:
        lines += ["*NODE PRINT, NSET=NALL", "U",
                  "*NODE PRINT, NSET=BOTTOM", "RF",
                  "*NODE PRINT, NSET=TOP", "RF"]
    lines.append("*END STEP")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
