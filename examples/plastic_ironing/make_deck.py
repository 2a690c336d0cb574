#!/usr/bin/env python3
"""Writes the plastic ironing deck: the ironing problem of tools/make_ironing_deck.py
(an elastic half-disc die, radius 5 mm, pressed 0.02 mm into a block and slid
along it, NLGEOM, plane strain) with an elastoplastic block: E = 200000 MPa,
nu = 0.3, von Mises with linear isotropic hardening from a yield stress of
500 MPa to 700 MPa at PEEQ 0.1 (flat beyond). The die stays elastic.
Frictionless (mu = 0) unless --mu is given, so that the drag is the plastic
ploughing alone. Shorter than the elastic example: a 1 mm slide (about twice
the contact width) in 40 increments of 0.025 mm (the plastic groove depends
on the path: 10 increments of 0.1 mm give a drag 22 % lower).

usage: make_deck.py OUT.inp [--yield 500] [--hardened 700] [--slide 1] [--slide-increments 40]
                            [--mu 0] [other options of tools/make_ironing_deck.py]
       (needs gmsh, as tools/make_ironing_deck.py does; extra options go to it)
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
TOOL = os.path.join(HERE, "..", "..", "tools", "make_ironing_deck.py")


def plastic(text, sy, sh):
    """The deck text with *PLASTIC after the block's *ELASTIC and the yield stress in the heading."""
    lines = text.split("\n")
    at = lines.index("*MATERIAL, NAME=BLOCK")
    if not lines[at + 1].startswith("*ELASTIC"):
        raise SystemExit("make_deck.py: no *ELASTIC after *MATERIAL, NAME=BLOCK")
    lines[at + 3:at + 3] = ["*PLASTIC", f"{sy:g}, 0.", f"{sh:g}, 0.1"]
    heading = lines.index("*HEADING") + 1
    lines[heading] += f" block_yield={sy:g} block_hardened={sh:g}"
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--yield", dest="sy", type=float, default=500.0, help="initial yield stress [MPa]")
    ap.add_argument("--hardened", type=float, default=700.0, help="yield stress at PEEQ 0.1 [MPa]")
    ap.add_argument("--slide", type=float, default=1.0)
    ap.add_argument("--slide-increments", type=int, default=40)
    opts, extra = ap.parse_known_args()
    if not any(a == "--mu" or a.startswith("--mu=") for a in extra):
        extra += ["--mu", "0"]
    subprocess.run([sys.executable, TOOL, opts.out, "--slide", f"{opts.slide:g}", "--slide-increments",
                    str(opts.slide_increments)] + extra, check=True)
    with open(opts.out) as f:
        text = f.read()
    text = text.replace("** written by tools/make_ironing_deck.py",
                        "** written by examples/plastic_ironing/make_deck.py (block made plastic) from "
                        "tools/make_ironing_deck.py", 1)
    with open(opts.out, "w") as f:
        f.write(plastic(text, opts.sy, opts.hardened))


if __name__ == "__main__":
    main()
