#!/usr/bin/python3
"""Runs the Hertz deck with node-to-segment and with mortar contact and plots both pressures over the exact curve.

    plot_hertz_mortar.py [--tether PATH] [--out DIR] [--png hertz_mortar.png]

hertz.inp (tools/make_hertz_deck.py --dofs 5k) has *CONTACT PAIR, TYPE=NODE TO SURFACE;
the script writes DIR/hertz_mortar.inp, the same deck with TYPE=SURFACE TO SURFACE, runs
`tether run` on both into DIR (default out/), and calls tools/hertz_summary.py on the two
.dat files, which prints the errors against Hertz and draws the PNG (matplotlib).
"""
import argparse
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--tether", default=shutil.which("tether") or os.path.join(ROOT, "build", "bin", "tether"))
    ap.add_argument("--out", default="out")
    ap.add_argument("--png", default=os.path.join(HERE, "hertz_mortar.png"))
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    deck = os.path.join(HERE, "hertz.inp")
    with open(deck) as f:
        text = f.read()
    if "TYPE=NODE TO SURFACE" not in text:
        sys.exit(f"{deck}: no TYPE=NODE TO SURFACE pair")
    decks = {"hertz_nts": text, "hertz_mortar": text.replace("TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE", 1)}
    dats = []
    for name, body in decks.items():
        path = os.path.join(a.out, name + ".inp")
        with open(path, "w") as f:
            f.write(body)
        subprocess.run([a.tether, "run", "-q", path, "-o", os.path.join(a.out, name)], check=True)
        dats.append(os.path.join(a.out, name, name + ".dat"))
    subprocess.run([sys.executable, os.path.join(ROOT, "tools", "hertz_summary.py"), *dats, "--deck", deck,
                    "--label", "node-to-segment", "--label", "mortar", "--png", a.png], check=True)


if __name__ == "__main__":
    main()
