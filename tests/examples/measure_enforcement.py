#!/usr/bin/env python3
"""Measures what each enforcement method gives on the seed's equality tie.

Usage: measure_enforcement.py TETHER_EXE WORK_DIR

Two CPE4 bars [0,1] and [1,2] (E = 1000, nu = 0, unit area; nodes not shared)
are joined at x = 1 by four ties u(a) = u(b) (*EQUATION), the left end is held
and the right end pulled by 10: exact tip displacement 0.02, tie force 5 on the
x ties. Runs the deck with every enforcement and prints a Markdown table of the
tip error, max |f|, lambda and the Newton iterations reported by `tether run`.
The figures in docs/theory/constraints.md come from this script.
"""
import os
import re
import subprocess
import sys

import tethertools.dat  # PYTHONPATH=tools

CASES = [
    ("LAGRANGE", ""),
    ("LAGRANGE, EPSILON=1e-9", ", ENFORCEMENT=LAGRANGE, EPSILON=1e-9"),
    ("LAGRANGE, EPSILON=1e-6", ", ENFORCEMENT=LAGRANGE, EPSILON=1e-6"),
    ("PENALTY=1e3", ", ENFORCEMENT=PENALTY, PENALTY=1e3"),
    ("PENALTY=1e6", ", ENFORCEMENT=PENALTY, PENALTY=1e6"),
    ("PENALTY=1e9", ", ENFORCEMENT=PENALTY, PENALTY=1e9"),
    ("AUGMENTED, PENALTY=1e3, TOLERANCE=1e-12", ", ENFORCEMENT=AUGMENTED, PENALTY=1e3, TOLERANCE=1e-12"),
    ("AUGMENTED, PENALTY=1e4, TOLERANCE=1e-12", ", ENFORCEMENT=AUGMENTED, PENALTY=1e4, TOLERANCE=1e-12"),
    ("ELIMINATION", ", ENFORCEMENT=ELIMINATION"),
]


def deck(parameters):
    lines = ["*NODE, NSET=NALL", "1,0,0", "2,1,0", "3,1,1", "4,0,1", "5,1,0", "6,2,0", "7,2,1", "8,1,1",
             "*ELEMENT, TYPE=CPE4, ELSET=E", "1, 1,2,3,4", "2, 5,6,7,8",
             "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.", "*SOLID SECTION, ELSET=E, MATERIAL=M",
             "*BOUNDARY", "1, 1, 2", "4, 1"]
    names = iter(["BX", "BY", "TX", "TY"])
    for a, b in ((2, 5), (3, 8)):
        for dof in (1, 2):
            lines += [f"*EQUATION, NAME={next(names)}{parameters}", "2", f"{a}, {dof}, 1., {b}, {dof}, -1."]
    lines += ["*STEP", "*STATIC", "*CONTROLS, PARAMETERS=FIELD", "1e-10, 1e-10",
              "*CLOAD", "6, 1, 5.", "7, 1, 5.", "*NODE PRINT, NSET=NALL", "U", "*END STEP"]
    return "\n".join(lines) + "\n"


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    tether, work = argv[1], argv[2]
    os.makedirs(work, exist_ok=True)
    print("| enforcement | tip u_x − 0.02 | max abs(f) | λ (x tie) | Newton iterations |")
    print("| --- | --- | --- | --- | --- |")
    for label, parameters in CASES:
        path = os.path.join(work, "tie.inp")
        with open(path, "w") as f:
            f.write(deck(parameters))
        out = os.path.join(work, "out")
        run = subprocess.run([tether, "run", path, "-o", out], capture_output=True, text=True, timeout=60)
        if run.returncode != 0:
            message = (run.stderr.strip().splitlines() or ["?"])[-1]
            print(f"| {label} | not run: {message} | | | |")
            continue
        iterations = re.search(r"(\d+) iterations", run.stdout)
        blocks = tethertools.dat.read(os.path.join(out, "tie.dat"))
        u = {int(r[0]): r for r in tethertools.dat.last_block(blocks, "displacements", "NALL")["rows"]}
        mult = [b for b in blocks if b["title"].startswith("constraint multipliers")]
        f_max = max((abs(r[2]) for b in mult for r in b["rows"]), default=float("nan"))
        lam = next((b["rows"][0][3] for b in mult if b["set"] == "BX"), float("nan"))
        print(f"| {label} | {u[6][1] - 0.02:.1e} | {f_max:.1e} | {lam:.6f} | "
              f"{iterations.group(1) if iterations else '?'} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
