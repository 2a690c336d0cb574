#!/usr/bin/env python3
"""Compares a Lame cylinder run (deck from make_lame_deck.py) with the exact solution.

Usage: lame_summary.py JOB.dat [JOB.inp]
Prints the radial displacement at the bore and the outer surface, computed and
exact, and exits 1 if the bore value is off by more than 0.5 %.
"""
import math
import sys

import tethertools.dat
from tethertools.make_lame_deck import A, B, E, NU, P


def exact_ur(r):
    return (1 + NU) * P * A * A / (E * (B * B - A * A)) * ((1 - 2 * NU) * r + B * B / r)


def radial(rows):
    return [math.hypot(row[1], row[2]) for row in rows]


def main():
    blocks = tethertools.dat.read(sys.argv[1])
    worst = 0.0
    print(f"Lame cylinder, plane strain: a = {A} mm, b = {B} mm, p = {P} MPa, E = {E:g} MPa, nu = {NU}")
    for name, r in (("INNER", A), ("OUTER", B)):
        values = radial(tethertools.dat.last_block(blocks, "displacements", name)["rows"])
        mean = sum(values) / len(values)
        exact = exact_ur(r)
        error = (mean - exact) / exact
        if name == "INNER":
            worst = abs(error)
        print(f"  u_r(r = {r:g}) computed {mean:.6e} mm   exact {exact:.6e} mm   error {100 * error:+.4f} %"
              f"   (mean of {len(values)} nodes)")
    if worst > 5e-3:
        print("FAILED: bore displacement off by more than 0.5 %")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
