#!/usr/bin/env python3
"""Writes an ABAQUS/CalculiX deck of a plane cantilever under an end shear load.

The beam occupies [0, L] x [0, H] (thickness T), is clamped at x = 0 (u = v = 0
on every node of the root) and carries a shear force P T in +y on the free end
x = L (P per unit thickness), distributed parabolically over the depth as in the
Timoshenko-Goodier solution, tau(y) = 6 P / H^3 * y (H - y), lumped to consistent
nodal forces. The deflection does not depend on T.

Beam theory (Timoshenko, shear coefficient k = 5/6) for the tip deflection:
  delta = P L^3 / (3 E I) + P L / (k G A),  I = H^3 / 12, A = H (per unit thickness), G = E / (2 (1 + nu))
The 2D elasticity solution of the clamped beam differs from it by a fraction of
the shear term, which is itself 0.6 (1 + nu) (H / L)^2 of the bending term
(0.8 % at L/H = 10): beam theory is an exact answer to well under 1 %.

Node sets: ROOT (x = 0), TIP (x = L), TIPMID (the tip node on the axis y = H/2;
--ny must be even for 4-node quads), NALL. Element set EALL.

Usage: make_cantilever_deck.py OUT.inp [--type CPS8] [--nx 20] [--ny 2] [--length 10] [--thickness 1]
                              [--print-all]
  --print-all  also print U of every node (NALL) and RF of every ROOT node (for tools/ccx_reference.py)
"""
import argparse
import math

H, T, P, E, NU = 1.0, 1.0, 100.0, 200000.0, 0.3


def tip_deflection(length, height=H, load=P, young=E, poisson=NU):
    """Timoshenko beam tip deflection (load per unit thickness)."""
    inertia = height ** 3 / 12
    shear_modulus = young / (2 * (1 + poisson))
    return load * length ** 3 / (3 * young * inertia) + load * length / (5 / 6 * shear_modulus * height)


def traction(y):
    """Shear traction on the end face at height y (force per area)."""
    return 6 * P / H ** 3 * y * (H - y)


def edge_loads(ys, thickness):
    """Consistent nodal forces of the traction on the edge through the nodes at heights ys
    (2 nodes: linear, 3 nodes: quadratic, ends first then middle), by 4-point Gauss."""
    g = [(-0.861136311594053, 0.347854845137454), (-0.339981043584856, 0.652145154862546),
         (0.339981043584856, 0.652145154862546), (0.861136311594053, 0.347854845137454)]
    forces = [0.0] * len(ys)
    for xi, w in g:
        if len(ys) == 2:
            n = [(1 - xi) / 2, (1 + xi) / 2]
        else:
            n = [xi * (xi - 1) / 2, xi * (xi + 1) / 2, 1 - xi * xi]
        y = sum(na * ya for na, ya in zip(n, ys))
        jac = (ys[1] - ys[0]) / 2
        for a in range(len(ys)):
            forces[a] += w * n[a] * traction(y) * jac * thickness
    return forces


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--type", default="CPS8")
    ap.add_argument("--nx", type=int, default=20, help="elements along the length")
    ap.add_argument("--ny", type=int, default=2, help="elements through the depth")
    ap.add_argument("--length", type=float, default=10.0)
    ap.add_argument("--thickness", type=float, default=T)
    ap.add_argument("--print-all", action="store_true", help="also print U of all nodes and RF of the root nodes")
    args = ap.parse_args()
    etype = args.type.upper()
    quadratic = etype[3] == "8"
    if etype[3] not in "48":
        raise SystemExit(f"{etype}: only 4- and 8-node quadrilaterals")
    m = 2 if quadratic else 1
    nx, ny, length = args.nx, args.ny, args.length
    if not quadratic and ny % 2:
        raise SystemExit("--ny must be even for 4-node elements (TIPMID needs a node on the axis)")
    ids = {}

    def node(i, j):
        if (i, j) not in ids:
            ids[(i, j)] = len(ids) + 1
        return ids[(i, j)]

    elements = []
    for j in range(ny):
        for i in range(nx):
            i0, j0 = m * i, m * j
            conn = [(i0, j0), (i0 + m, j0), (i0 + m, j0 + m), (i0, j0 + m)]
            if quadratic:
                conn += [(i0 + 1, j0), (i0 + 2, j0 + 1), (i0 + 1, j0 + 2), (i0, j0 + 1)]
            elements.append([node(*ij) for ij in conn])

    def position(i, j):
        return length * i / (m * nx), H * j / (m * ny)

    lines = ["*HEADING", f"Cantilever L={length:g} H={H:g} T={args.thickness:g} P={P:g} per unit thickness ({etype}, {nx}x{ny})", "*NODE, NSET=NALL"]
    for (i, j), n in sorted(ids.items(), key=lambda kv: kv[1]):
        x, y = position(i, j)
        lines.append(f"{n}, {x:.15g}, {y:.15g}")
    lines.append(f"*ELEMENT, TYPE={etype}, ELSET=EALL")
    for k, conn in enumerate(elements, 1):
        lines.append(f"{k}, " + ", ".join(map(str, conn)))

    def nset(name, members):
        lines.append(f"*NSET, NSET={name}")
        for k in range(0, len(members), 16):
            lines.append(", ".join(map(str, members[k:k + 16])))

    imax = m * nx
    root = sorted(n for (i, j), n in ids.items() if i == 0)
    tip = sorted(n for (i, j), n in ids.items() if i == imax)
    nset("ROOT", root)
    nset("TIP", tip)
    nset("TIPMID", [ids[(imax, m * ny // 2)]])
    loads = {}
    for j in range(ny):
        j0 = m * j
        edge = [(imax, j0), (imax, j0 + m)] + ([(imax, j0 + 1)] if quadratic else [])
        for ij, f in zip(edge, edge_loads([position(*ij)[1] for ij in edge], args.thickness)):
            loads[ids[ij]] = loads.get(ids[ij], 0.0) + f
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL", f"{args.thickness:g}",
              "*BOUNDARY", "ROOT, 1, 2",
              "*STEP", "*STATIC", "1., 1.", "*CLOAD"]
    lines += [f"{n}, 2, {f:.15g}" for n, f in sorted(loads.items())]
    lines += ["*NODE PRINT, NSET=TIPMID", "U",
              "*NODE PRINT, NSET=ROOT, TOTALS=ONLY", "RF"]
    if args.print_all:
        lines += ["*NODE PRINT, NSET=NALL", "U", "*NODE PRINT, NSET=ROOT", "RF"]
    lines.append("*END STEP")
    with open(args.out, "w") as f:
        f.write("\n".join(lines) + "\n")
    assert math.isclose(sum(loads.values()), P * args.thickness, rel_tol=1e-12)


if __name__ == "__main__":
    main()
