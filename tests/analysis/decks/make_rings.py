#!/usr/bin/env python3
"""Writes rings.inp: two identical elastic rings (plane strain, CPE4, NLGEOM)
flying at each other off centre, explicit, frictionless node-to-surface
contact (ring A's outer face slave, ring B's master).

    python3 tests/analysis/decks/make_rings.py [--n-theta 48] [--n-radial 3] > rings.inp

Ring: outer radius 0.1 m, inner 0.08 m, E 1e7 Pa, nu 0.3, rho 1000 kg/m^3.
A at (-0.105, 0.04) moving at (+5, 0) m/s, B at (0.105, -0.04) moving at (-5, 0).
"""
import argparse
import math


def ring(out, first_node, first_element, centre, r_in, r_out, n_theta, n_radial, name):
    """Nodes (radial i, angular j) = first_node + j (n_radial + 1) + i; CPE4
    (i, j) counter-clockwise, its face S2 on radius i + 1 (the outer face for
    i = n_radial - 1)."""
    out.append(f"*NODE, NSET={name}N")
    for j in range(n_theta):
        theta = 2 * math.pi * j / n_theta
        for i in range(n_radial + 1):
            r = r_in + (r_out - r_in) * i / n_radial
            out.append(f"{first_node + j * (n_radial + 1) + i}, {centre[0] + r * math.cos(theta):.17g}, "
                       f"{centre[1] + r * math.sin(theta):.17g}")
    out.append(f"*ELEMENT, TYPE=CPE4, ELSET={name}")
    outer = []
    for j in range(n_theta):
        jn = (j + 1) % n_theta
        for i in range(n_radial):
            a = first_node + j * (n_radial + 1) + i
            b = first_node + jn * (n_radial + 1) + i
            e = first_element + j * n_radial + i
            out.append(f"{e}, {a}, {a + 1}, {b + 1}, {b}")
            if i == n_radial - 1:
                outer.append(e)
    out.append(f"*SURFACE, NAME={name}OUT")
    out.extend(f"{e}, S2" for e in outer)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--n-theta", type=int, default=48, help="elements around each ring")
    parser.add_argument("--n-radial", type=int, default=3, help="elements through each ring's wall")
    parser.add_argument("--period", type=float, default=0.03, help="step time [s]")
    args = parser.parse_args()
    out = ["*HEADING", "Two identical elastic rings colliding off centre (explicit, frictionless; make_rings.py)"]
    ring(out, 1, 1, (-0.105, 0.04), 0.08, 0.1, args.n_theta, args.n_radial, "A")
    ring(out, 10001, 10001, (0.105, -0.04), 0.08, 0.1, args.n_theta, args.n_radial, "B")
    out += ["*MATERIAL, NAME=RUBBERY", "*ELASTIC", "1e7, 0.3", "*DENSITY", "1000.",
            "*SOLID SECTION, ELSET=A, MATERIAL=RUBBERY", "1.", "*SOLID SECTION, ELSET=B, MATERIAL=RUBBERY", "1.",
            "*SURFACE INTERACTION, NAME=FRICTIONLESS", "*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=NODE TO SURFACE",
            "AOUT, BOUT", "*INITIAL CONDITIONS, TYPE=VELOCITY", "AN, 1, 5.", "BN, 1, -5.",
            "*STEP, NLGEOM", "*DYNAMIC, EXPLICIT", f", {args.period:g}",
            "*NODE PRINT, FREQUENCY=10", "U, V", "*CONTACT PRINT, FREQUENCY=10", "*END STEP"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
