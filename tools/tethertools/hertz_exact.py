#!/usr/bin/python3
"""Exact plane-strain Hertz contact of a cylinder on a flat (line load per unit length).

    E* = 1 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)     contact modulus
         = E / (2 (1 - nu^2))   cylinder and block of the same material
         = E / (1 - nu^2)       cylinder on a rigid flat
    a  = sqrt(4 P R / (pi E*))                       half-width of the contact strip
    p0 = 2 P / (pi a)                                peak pressure (at x = 0)
    p(x) = p0 sqrt(1 - x^2 / a^2)  for |x| <= a, 0 outside

P is the force per unit length of the whole cylinder (N/mm); the symmetric half
model of tools/make_hertz_deck.py carries P/2 and the integral of p over x >= 0.

Usage: hertz_exact.py [--R 10] [--E 200000] [--nu 0.3] [--P 2000] [--rigid-flat] [--json]
Prints E*, a, p0 (and the approach is not given: in 2D it depends on the body sizes).
"""
import argparse
import json
import math
import sys

R, E, NU, P = 10.0, 200000.0, 0.3, 2000.0


def contact_modulus(E=E, nu=NU, rigid_flat=False):
    """E* of two bodies of (E, nu), or of one body on a rigid flat."""
    e1 = (1.0 - nu * nu) / E
    return 1.0 / (e1 if rigid_flat else 2.0 * e1)


def hertz(P=P, R=R, E=E, nu=NU, rigid_flat=False):
    """dict(Estar, a, p0) of the plane-strain Hertz problem (P per unit length of the whole cylinder)."""
    estar = contact_modulus(E, nu, rigid_flat)
    a = math.sqrt(4.0 * P * R / (math.pi * estar))
    p0 = 2.0 * P / (math.pi * a)
    return {"Estar": estar, "a": a, "p0": p0, "P": P, "R": R, "E": E, "nu": nu, "rigid_flat": rigid_flat}


def pressure(x, a, p0):
    """Exact pressure at x (scalar or numpy array)."""
    try:
        import numpy as np
        if not isinstance(x, (int, float)):
            x = np.asarray(x, dtype=float)
            return p0 * np.sqrt(np.clip(1.0 - (x / a) ** 2, 0.0, None))
    except ImportError:
        pass
    return p0 * math.sqrt(max(0.0, 1.0 - (x / a) ** 2))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--R", type=float, default=R, help="cylinder radius [mm] (default 10)")
    ap.add_argument("--E", type=float, default=E, help="Young's modulus [MPa] (default 200000)")
    ap.add_argument("--nu", type=float, default=NU, help="Poisson's ratio (default 0.3)")
    ap.add_argument("--P", type=float, default=P, help="line load of the whole cylinder [N/mm] (default 2000)")
    ap.add_argument("--rigid-flat", action="store_true", help="cylinder on a rigid flat (else on a block of the same material)")
    ap.add_argument("--json", action="store_true", help="print JSON instead of text")
    args = ap.parse_args(argv)
    cases = [args.rigid_flat] if args.rigid_flat else [False, True]
    results = [hertz(args.P, args.R, args.E, args.nu, rf) for rf in cases]
    if args.json:
        print(json.dumps(results if len(results) > 1 else results[0], indent=2))
        return 0
    print(f"plane-strain Hertz: R = {args.R:g} mm, E = {args.E:g} MPa, nu = {args.nu:g}, P = {args.P:g} N/mm "
          f"(half model: P/2 = {args.P / 2:g} N/mm)")
    for h in results:
        name = "rigid flat  " if h["rigid_flat"] else "elastic block"
        print(f"  {name}  E* = {h['Estar']:.6g} MPa   a = {h['a']:.6g} mm   p0 = {h['p0']:.6g} MPa")
    return 0


if __name__ == "__main__":
    sys.exit(main())
