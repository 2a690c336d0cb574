#!/usr/bin/env python3
"""Writes Cook's membrane at finite strain with saturation hardening (Simo and
Armero 1992) as an ABAQUS/CalculiX deck: the trapezoid (0,0), (48,44), (48,60),
(0,44), clamped on the left, a dead shear load of total 5 (per unit thickness)
on the right edge, plane strain, NLGEOM. Elastic K = 164.206, mu = 80.1938
(E = 206.9, nu = 0.29); yield stress y(p) = 0.45 + 0.265 (1 - exp(-16.93 p))
+ 0.12924 p, written as a *PLASTIC table.

usage: make_deck.py N [--type CPE8R] > cook_N.inp   (N x N elements)
"""
import argparse
import math


def yield_stress(p):
    return 0.45 + (0.715 - 0.45) * (1 - math.exp(-16.93 * p)) + 0.12924 * p


def node_at(xi, eta):
    """Reference point of the membrane at unit coordinates (xi along x, eta along the height)."""
    x = 48.0 * xi
    bottom, top = 44.0 * xi, 44.0 + 16.0 * xi
    return x, bottom + eta * (top - bottom)


def write(n, element, out):
    quadratic = element.endswith("8") or element.endswith("8R")
    m = 2 * n if quadratic else n  # node grid intervals per side
    ids = {}
    lines = []
    for j in range(m + 1):
        for i in range(m + 1):
            if quadratic and i % 2 == 1 and j % 2 == 1:
                continue  # no centre nodes in 8-node elements
            ids[(i, j)] = len(ids) + 1
            x, y = node_at(i / m, j / m)
            lines.append(f"{ids[(i, j)]}, {x:.12g}, {y:.12g}")
    print("** Cook's membrane, elastoplastic with saturation hardening, finite strain (Simo and Armero 1992).", file=out)
    print(f"** Written by examples/cook_membrane/make_deck.py {n} --type {element}.", file=out)
    print("*HEADING", file=out)
    print(f"Cook's membrane {n}x{n} {element}, J2 saturation hardening, NLGEOM, shear load 5", file=out)
    print("*NODE, NSET=NALL", file=out)
    print("\n".join(lines), file=out)
    print(f"*ELEMENT, TYPE={element}, ELSET=EALL", file=out)
    s = 2 if quadratic else 1
    for j in range(n):
        for i in range(n):
            a, b = s * i, s * j
            corners = [ids[(a, b)], ids[(a + s, b)], ids[(a + s, b + s)], ids[(a, b + s)]]
            if quadratic:
                corners += [ids[(a + 1, b)], ids[(a + 2, b + 1)], ids[(a + 1, b + 2)], ids[(a, b + 1)]]
            print(f"{j * n + i + 1}, " + ", ".join(map(str, corners)), file=out)
    print("*NSET, NSET=LEFT", file=out)
    print("\n".join(str(ids[(0, j)]) for j in range(m + 1) if (0, j) in ids), file=out)
    print("*NSET, NSET=TIP", file=out)
    print(ids[(m, m)], file=out)
    print("*MATERIAL, NAME=SATURATION", file=out)
    print("*ELASTIC\n206.9, 0.29", file=out)
    print("*PLASTIC", file=out)
    rows = 100
    for k in range(rows):
        p = 2.0 * (k / (rows - 1)) ** 2
        print(f"{yield_stress(p):.10g}, {p:.10g}", file=out)
    print("*SOLID SECTION, ELSET=EALL, MATERIAL=SATURATION\n1.", file=out)
    print("*BOUNDARY\nLEFT, 1, 2", file=out)
    print("*STEP, NLGEOM, INC=1000\n*STATIC\n0.1, 1., 1e-5, 0.1", file=out)
    # Consistent nodal forces of the uniform shear traction 5/16 on the right edge.
    weights = {}
    for j in range(n):
        edge = [(m, s * j), (m, s * j + s)] + ([(m, s * j + 1)] if quadratic else [])
        share = [1 / 6, 1 / 6, 4 / 6] if quadratic else [0.5, 0.5]
        for node, w in zip(edge, share):
            weights[ids[node]] = weights.get(ids[node], 0.0) + w * 5.0 / n
    print("*CLOAD", file=out)
    for node in sorted(weights):
        print(f"{node}, 2, {weights[node]:.12g}", file=out)
    print("*NODE PRINT, NSET=TIP\nU\n*END STEP", file=out)


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("n", type=int, help="elements per side")
    parser.add_argument("--type", default="CPE8R", help="element type (CPE8R, CPE4, ...)")
    args = parser.parse_args()
    import sys

    write(args.n, args.type, sys.stdout)
