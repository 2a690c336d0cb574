#!/usr/bin/env python3
"""Runs decks through CalculiX (ccx) and writes reference CSVs for the verification tests.

For each deck, ccx runs in its own scratch directory (`ccx -i JOB`, under
`timeout`); its .dat is parsed with tools/tethertools/dat.py and two kinds of rows are
written to tests/verification/reference/JOB.csv:

  kind,set,node,x,y      U  rows: displacement of every node of NALL
                         RF rows: reaction of every node of the reaction sets

ccx expands 2D elements into one-layer 3D elements internally but prints *NODE
PRINT results at the original 2D node ids (checked: the ids in the .dat are
those of the deck), so no renumbering is needed. ccx prints 7 significant
digits (E13.6), which bounds how closely any code can be compared with it.

Note on RF: ccx's RF is the internal nodal force, tether's reaction is the
internal force minus the applied load; they are equal only at nodes that carry
no load, so the test compares RF only there.

Usage: ccx_reference.py [DECK.inp ...]   (default: the ccx_*.inp decks of tests/verification/decks)
"""
import csv
import glob
import os
import shutil
import subprocess
import sys
import tempfile

import tethertools.dat

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # tools/: the scripts
ROOT = os.path.normpath(os.path.join(TOOLS, ".."))

DECKS = os.path.join(ROOT, "tests", "verification", "decks")
REFERENCE = os.path.join(ROOT, "tests", "verification", "reference")
REACTION_SETS = ("BOTTOM", "TOP", "ROOT")


def ccx_version():
    out = subprocess.run(["timeout", "60", "ccx", "-v"], capture_output=True, text=True).stdout
    return " ".join(line.strip() for line in out.splitlines() if "Version" in line) or "unknown"


def run_ccx(deck):
    """Runs ccx on a copy of `deck` in a scratch directory; returns the parsed .dat blocks."""
    job = os.path.splitext(os.path.basename(deck))[0]
    with tempfile.TemporaryDirectory(prefix=f"ccx_{job}_") as work:
        shutil.copy(deck, os.path.join(work, job + ".inp"))
        env = dict(os.environ, OMP_NUM_THREADS="1")
        proc = subprocess.run(["timeout", "300", "ccx", "-i", job], cwd=work, capture_output=True, text=True, env=env)
        if proc.returncode != 0 or "Job finished" not in proc.stdout:
            sys.stderr.write(proc.stdout[-3000:] + proc.stderr[-3000:])
            raise SystemExit(f"{deck}: ccx failed (exit {proc.returncode})")
        return tethertools.dat.read(os.path.join(work, job + ".dat"))


def write_reference(deck, blocks, version):
    job = os.path.splitext(os.path.basename(deck))[0]
    os.makedirs(REFERENCE, exist_ok=True)
    path = os.path.join(REFERENCE, job + ".csv")
    rows = []
    for row in tethertools.dat.last_block(blocks, "displacements", "NALL")["rows"]:
        rows.append(["U", "NALL", int(row[0]), row[1], row[2]])
    for name in REACTION_SETS:
        try:
            block = tethertools.dat.last_block(blocks, "forces", name)
        except KeyError:
            continue
        for row in block["rows"]:
            rows.append(["RF", name, int(row[0]), row[1], row[2]])
    with open(path, "w", newline="") as f:
        f.write(f"# CalculiX reference for {os.path.relpath(deck, ROOT)}; written by tools/ccx_reference.py\n")
        f.write(f"# {version}\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(["kind", "set", "node", "x", "y"])
        for r in rows:
            w.writerow(r[:3] + [f"{r[3]:.6e}", f"{r[4]:.6e}"])
    print(f"{path}: {len(rows)} rows")


def main():
    decks = sys.argv[1:] or sorted(glob.glob(os.path.join(DECKS, "ccx_*.inp")))
    if shutil.which("ccx") is None:
        raise SystemExit("ccx not found (Debian package calculix-ccx)")
    version = ccx_version()
    for deck in decks:
        write_reference(deck, run_ccx(deck), version)


if __name__ == "__main__":
    main()
