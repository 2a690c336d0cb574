#!/usr/bin/env python3
"""Deck of the perfectly plastic thick cylinder under internal pressure.

    python3 make_deck.py [NR NT] > cylinder.inp

A quarter of a ring a = 10, b = 20 mm in plane strain (CPE8R, NR elements
through the wall, NT around; 24 x 8 by default), E = 200000 MPa, nu = 0.3,
von Mises yield 240 MPa without hardening. Step 1 raises the bore pressure
to 190 MPa in fixed increments of 9.5 MPa (the limit pressure is
(2/sqrt3) 240 ln 2 = 192.09 MPa); step 2 takes it back to 0. The mesh comes
from tools/make_lame_deck.py; U of the bore and outer nodes, PEEQ and
AC YIELD of every point are printed at each increment.
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
MAKE_LAME = os.path.join(HERE, "..", "..", "tools", "make_lame_deck.py")

MODEL = """*MATERIAL, NAME=STEEL
*ELASTIC
200000., 0.3
*PLASTIC
240., 0.
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
1.
*BOUNDARY
BOTTOM, 2, 2
TOP, 1, 1
"""

STEP = """*STEP, INC=100
*STATIC, DIRECT
{increment}, 1.
*DSLOAD
BORE, P, {pressure}
*NODE PRINT, NSET=INNER
U
*NODE PRINT, NSET=OUTER
U
*EL PRINT, ELSET=EALL
PEEQ, AC YIELD
*NODE FILE
U
*EL FILE
S, PEEQ, AC YIELD
*END STEP
"""


def main():
    nr, nt = (int(sys.argv[1]), int(sys.argv[2])) if len(sys.argv) > 2 else (24, 8)
    with tempfile.TemporaryDirectory() as tmp:
        base = os.path.join(tmp, "base.inp")
        subprocess.run([sys.executable, MAKE_LAME, base, "--type", "CPE8R", "--nr", str(nr), "--nt", str(nt)],
                       check=True)
        with open(base) as f:
            mesh = f.read().split("*MATERIAL")[0]
    lines = mesh.splitlines(keepends=True)
    heading = (f"** Perfectly plastic thick cylinder (examples/plastic_cylinder/make_deck.py {nr} {nt})\n"
               f"*HEADING\nThick cylinder a=10 b=20, plane strain CPE8R {nr}x{nt}, von Mises 240 MPa, "
               "bore pressure to 190 MPa and back\n")
    body = "".join(lines[2:]) if lines[0].startswith("*HEADING") else mesh
    sys.stdout.write(heading + body + MODEL + STEP.format(increment=0.05, pressure=190.)
                     + STEP.format(increment=0.25, pressure=0.))


if __name__ == "__main__":
    main()
