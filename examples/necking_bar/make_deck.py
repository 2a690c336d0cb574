#!/usr/bin/env python3
"""Writes the necking of a circular bar (Simo 1988; Simo and Armero 1992;
Simo and Hughes, Computational Inelasticity, section 9.4) as an ABAQUS/CalculiX
deck: half of a bar of radius 6.413 mm and length 53.334 mm, axisymmetric
(CAX8R: r = x, axis = y), cut at its centre plane y = 0 (symmetry: u_y = 0),
the end y = 26.667 pulled by 7 mm (14 mm for the whole bar) with u_r = 0.
Imperfection: the radius grows linearly from 0.982 x 6.413 at y = 0 to 6.413
at the end. Units mm, GPa: E = 206.9, nu = 0.29; yield stress
y(p) = 0.45 + 0.12924 p + (0.715 - 0.45) (1 - exp(-16.93 p)), written as a
*PLASTIC table of 100 rows (p up to 2, finer near 0). NLGEOM, automatic
increments. Output: U of NECK (the outer node of the centre plane), RF totals
of END.

usage: make_deck.py NR NY [--type CAX8R] [--grading 3] [--fixed N] > necking.inp
       make_deck.py --vm318 [--type CAX4H] [--fixed N] > necking_vm318.inp
  NR x NY elements; element heights grow geometrically away from the centre
  plane, the last one GRADING times the first. --fixed N: N equal increments
  (*STATIC, DIRECT) instead of automatic ones.
  --vm318: the mesh and increments of the ANSYS Verification Manual's test
  VM318 (the same bar; its input deck is public in PyMAPDL, examples/verif/
  vm318.dat): 6 elements across, 8 equal ones from the centre plane to L/6 and
  4 equal ones from L/6 to the end, 50 equal increments (--fixed 0: the
  automatic increments of the other decks instead). Its element is the
  linear mixed u-P one: --type CAX4H (constant pressure, mean dilatation).
"""
import argparse
import math

RADIUS, HALF_LENGTH, IMPERFECTION, PULL = 6.413, 26.667, 0.018, 7.0


def yield_stress(p):
    return 0.45 + 0.12924 * p + (0.715 - 0.45) * (1 - math.exp(-16.93 * p))


def heights(n, grading):
    """y of the n + 1 element boundaries from 0 to HALF_LENGTH, geometric growth."""
    if n == 1 or grading == 1:
        return [HALF_LENGTH * j / n for j in range(n + 1)]
    q = grading ** (1 / (n - 1))
    sizes = [q ** j for j in range(n)]
    total = sum(sizes)
    ys, y = [0.0], 0.0
    for s in sizes:
        y += s * HALF_LENGTH / total
        ys.append(y)
    ys[-1] = HALF_LENGTH
    return ys


def vm318_heights():
    """VM318's element boundaries: 8 equal heights to L/6, 4 equal ones to L/2."""
    sixth = HALF_LENGTH / 3
    return [sixth * j / 8 for j in range(8)] + [sixth + (HALF_LENGTH - sixth) * j / 4 for j in range(5)]


def write(nr, ny, element, grading, out, ys=None, fixed=0, vm318=False):
    quadratic = element.startswith("CAX8")
    ys = heights(ny, grading) if ys is None else ys
    if quadratic:  # mid-side rows
        ys = [v for j in range(ny) for v in (ys[j], 0.5 * (ys[j] + ys[j + 1]))] + [ys[-1]]
    mr, my = (2 * nr, 2 * ny) if quadratic else (nr, ny)
    ids, lines = {}, []
    for j in range(my + 1):
        y = ys[j]
        outer = RADIUS * (1 - IMPERFECTION * (1 - y / HALF_LENGTH))
        for i in range(mr + 1):
            if quadratic and i % 2 == 1 and j % 2 == 1:
                continue
            ids[(i, j)] = len(ids) + 1
            lines.append(f"{ids[(i, j)]}, {outer * i / mr:.12g}, {y:.12g}")
    print("** Necking of a circular bar (Simo 1988; Simo and Armero 1992), half model, axisymmetric.", file=out)
    how = "--vm318" if vm318 else f"{nr} {ny} --grading {grading:g}"
    fixed_text = "" if (vm318 and fixed == 50) or (not vm318 and not fixed) else f" --fixed {fixed}"
    print(f"** Written by examples/necking_bar/make_deck.py {how} --type {element}{fixed_text}.", file=out)
    print("*HEADING", file=out)
    print(f"Necking bar {nr}x{ny} {element}, J2 saturation hardening, NLGEOM, pulled 7 mm", file=out)
    print("*NODE, NSET=NALL", file=out)
    print("\n".join(lines), file=out)
    print(f"*ELEMENT, TYPE={element}, ELSET=BAR", file=out)
    s = 2 if quadratic else 1
    for j in range(ny):
        for i in range(nr):
            a, b = s * i, s * j
            nodes = [ids[(a, b)], ids[(a + s, b)], ids[(a + s, b + s)], ids[(a, b + s)]]
            if quadratic:
                nodes += [ids[(a + 1, b)], ids[(a + 2, b + 1)], ids[(a + 1, b + 2)], ids[(a, b + 1)]]
            print(f"{j * nr + i + 1}, " + ", ".join(map(str, nodes)), file=out)
    on = lambda pred: "\n".join(str(n) for (i, j), n in sorted(ids.items(), key=lambda kv: kv[1]) if pred(i, j))
    print("*NSET, NSET=AXIS", file=out)
    print(on(lambda i, j: i == 0), file=out)
    print("*NSET, NSET=CENTRE", file=out)
    print(on(lambda i, j: j == 0), file=out)
    print("*NSET, NSET=END", file=out)
    print(on(lambda i, j: j == my), file=out)
    print("*NSET, NSET=NECK", file=out)
    print(ids[(mr, 0)], file=out)
    print("*MATERIAL, NAME=STEEL", file=out)
    print("*ELASTIC\n206.9, 0.29", file=out)
    print("*PLASTIC", file=out)
    rows = 100
    for k in range(rows):
        p = 2.0 * (k / (rows - 1)) ** 2
        print(f"{yield_stress(p):.10g}, {p:.10g}", file=out)
    print("*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL\n1.", file=out)
    print("*BOUNDARY\nAXIS, 1, 1\nCENTRE, 2, 2\nEND, 1, 1", file=out)
    if fixed:
        print(f"*STEP, NLGEOM, INC={fixed}\n*STATIC, DIRECT\n{1 / fixed:.12g}, 1.", file=out)
    else:
        print("*STEP, NLGEOM, INC=1000\n*STATIC\n0.01, 1., 1e-5, 0.02", file=out)
    print(f"*BOUNDARY\nEND, 2, 2, {PULL:g}", file=out)
    print("*NODE PRINT, NSET=NECK\nU\n*NODE PRINT, NSET=END, TOTALS=ONLY\nRF\n*END STEP", file=out)


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("nr", type=int, nargs="?")
    ap.add_argument("ny", type=int, nargs="?")
    ap.add_argument("--type", default="CAX8R", choices=["CAX4", "CAX4H", "CAX4R", "CAX8", "CAX8R"])
    ap.add_argument("--grading", type=float, default=3.0)
    ap.add_argument("--fixed", type=int, default=None,
                    help="N equal increments instead of automatic ones (0: automatic; --vm318: 50 unless given)")
    ap.add_argument("--vm318", action="store_true", help="VM318's 6 x 12 mesh and 50 equal increments")
    a = ap.parse_args()
    import sys
    if a.vm318:
        write(6, 12, a.type, 0, sys.stdout, ys=vm318_heights(), fixed=50 if a.fixed is None else a.fixed, vm318=True)
    elif a.nr is None or a.ny is None:
        ap.error("NR and NY are needed (or --vm318)")
    else:
        write(a.nr, a.ny, a.type, a.grading, sys.stdout, fixed=a.fixed or 0)
