#!/usr/bin/env python3
"""Writes the bar-impact deck: an elastic bar (plane strain, every node on
rollers in y: 1D strain) moving at v0 onto a rigid wall (a held CPE4 whose
face is the master surface), frictionless hard node-to-surface contact.

    python3 make_deck.py [--procedure explicit|implicit] [options] > bar_impact.inp

Steel: E 2e11 Pa, nu 0.3, rho 7800 kg/m^3; square CPE4 of side h, thickness 1.
Closed form (c_p^2 = E (1 - nu) / (rho (1 + nu)(1 - 2 nu)), A = h x 1):
contact for 2 L / c_p at the force rho c_p v0 A, then the bar leaves at +v0;
the kinetic energy falls linearly to 0 at L / c_p (the strain energy rises
to the initial kinetic energy) and returns linearly by 2 L / c_p.
The same deck runs in CalculiX (ccx): *DYNAMIC with or without EXPLICIT.
"""
import argparse


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--elements", type=int, default=100, help="CPE4 along the bar")
    parser.add_argument("--length", type=float, default=1.0, help="bar length L [m]")
    parser.add_argument("--v0", type=float, default=1.0, help="impact speed [m/s]")
    parser.add_argument("--procedure", choices=("explicit", "implicit"), default="explicit")
    parser.add_argument("--courant", type=float, default=1.0,
                        help="implicit: the time increment as a multiple of h / c_p")
    parser.add_argument("--solid", action="store_true",
                        help="write the same model as one layer of C3D8 (z held): CalculiX 2.20 ignores initial "
                             "velocities on plane elements (it expands them to C3D8 and the velocities stay on the "
                             "plane nodes), so this is the deck to compare with it")
    args = parser.parse_args()
    if args.solid:
        print("\n".join(solid(deck_lines(args), 2 * args.elements + 20)))
        return
    print("\n".join(deck_lines(args)))


def solid(lines, offset):
    """The plane deck `lines` extruded to one layer of C3D8 (thickness 1, every z held): node k at z = 0,
    node k + `offset` at z = 1; CPE4 faces S2 and S4 become C3D8 faces S4 and S6."""
    out, block = [], None
    for line in lines:
        if line.startswith("*"):
            block = line.split(",")[0].upper()
            if block == "*ELEMENT":
                line = line.replace("CPE4", "C3D8")
            elif block == "*BOUNDARY":
                out += [line, "ZHELD, 3, 3"]
                continue
            elif block == "*SOLID SECTION":
                out.append(line)
                continue
            out.append(line)
            continue
        values = [v.strip() for v in line.split(",")]
        if block == "*NODE":
            out += [f"{values[0]}, {values[1]}, {values[2]}, 0", f"{int(values[0]) + offset}, {values[1]}, {values[2]}, 1"]
        elif block == "*ELEMENT":
            corners = [int(v) for v in values[1:]]
            out.append(", ".join([values[0]] + [str(c) for c in corners] + [str(c + offset) for c in corners]))
        elif block == "*SURFACE":
            out.append(f"{values[0]}, " + {"S2": "S4", "S4": "S6"}[values[1]])
        elif block == "*NSET" or (block == "*BOUNDARY" and not values[0].isalpha()):
            out.append(", ".join(values + [str(int(v) + offset) for v in values if v.isdigit()]))
        elif block == "*SOLID SECTION":
            continue  # a solid section has no thickness line
        else:
            out.append(line)
    out.insert(out.index("*ELEMENT, TYPE=C3D8, ELSET=BAR"), "*NSET, NSET=ZHELD")
    out.insert(out.index("*NSET, NSET=ZHELD") + 1, "BARN, WALLN")
    return out


def deck_lines(args):
    """The plane deck's lines."""
    n, L, v0 = args.elements, args.length, args.v0
    h = L / n
    E, nu, rho = 2e11, 0.3, 7800.0
    cp = (E * (1 - nu) / (rho * (1 + nu) * (1 - 2 * nu))) ** 0.5
    period = 2.5 * L / cp
    out = ["*HEADING",
           f"Elastic bar on a rigid wall, 1D strain ({args.procedure}; examples/dyn_bar_impact/make_deck.py "
           f"--elements {n} --length {L:g} --v0 {v0:g} --procedure {args.procedure})", "*NODE, NSET=BARN"]
    out += [f"{i + 1}, {i * h:.17g}, 0" for i in range(n + 1)]
    out += [f"{n + 2 + i}, {i * h:.17g}, {h:.17g}" for i in range(n + 1)]
    w = 2 * n + 10
    out += ["*NODE, NSET=WALLN", f"{w + 1}, {-h:.17g}, {-h:.17g}", f"{w + 2}, 0, {-h:.17g}", f"{w + 3}, 0, {2 * h:.17g}",
            f"{w + 4}, {-h:.17g}, {2 * h:.17g}", "*ELEMENT, TYPE=CPE4, ELSET=BAR"]
    out += [f"{i + 1}, {i + 1}, {i + 2}, {n + 3 + i}, {n + 2 + i}" for i in range(n)]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=WALL", f"{n + 1}, {w + 1}, {w + 2}, {w + 3}, {w + 4}",
            "*NSET, NSET=IMPACT", f"1, {n + 2}",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {nu}", "*DENSITY", f"{rho:g}",
            "*SOLID SECTION, ELSET=BAR, MATERIAL=STEEL", "1.", "*SOLID SECTION, ELSET=WALL, MATERIAL=STEEL", "1.",
            "*SURFACE, NAME=BAREND, TYPE=ELEMENT", "1, S4", "*SURFACE, NAME=WALLFACE, TYPE=ELEMENT", f"{n + 1}, S2",
            "*SURFACE INTERACTION, NAME=HARD", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD",
            "*CONTACT PAIR, INTERACTION=HARD, TYPE=NODE TO SURFACE", "BAREND, WALLFACE",
            "*BOUNDARY", "BARN, 2, 2", "WALLN, 1, 2",
            "*INITIAL CONDITIONS, TYPE=VELOCITY", f"BARN, 1, {-v0:g}"]
    if args.procedure == "explicit":  # (tether: the first value only counts with DIRECT; CalculiX needs one)
        out += ["*STEP, INC=100000", "*DYNAMIC, EXPLICIT", f"{0.5 * h / cp:.6g}, {period:.6g}"]
    else:
        dt = args.courant * h / cp
        out += [f"*STEP, INC={int(period / dt) + 10}", "*DYNAMIC, DIRECT", f"{dt:.6g}, {period:.6g}"]
    if args.procedure == "explicit" and not args.solid:  # 100 points of history (an explicit step's default: 20)
        out += ["*OUTPUT, HISTORY, NUMBER INTERVAL=100", "*NODE OUTPUT, NSET=WALLN", "RF", "*NODE OUTPUT, NSET=IMPACT",
                "U, V", "*END STEP"]
    else:  # implicit: every increment; CalculiX (--solid): every explicit increment
        out += ["*NODE PRINT, NSET=WALLN", "RF", "*NODE PRINT, NSET=IMPACT", "U, V", "*END STEP"]
    return out


if __name__ == "__main__":
    main()
