#!/usr/bin/env python3
"""Checks tools/tethertools/dat.py (the reader the examples and tools use) against an
expectation in parse_dat.py's JSON format, so both readers are held to the same
blocks.

Usage: check_datfile.py FILE.dat EXPECTED.json   (exit status 0 when the file matches)
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))

import tethertools.dat  # noqa: E402
import parse_dat  # noqa: E402


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    blocks = tethertools.dat.read(argv[1])
    with open(argv[2], encoding="utf-8") as f:
        expected = json.load(f)
    errors = parse_dat.check(blocks, expected)
    for e in errors:
        print("check_datfile.py:", e, file=sys.stderr)
    print(f"check_datfile.py: {argv[1]}: {len(blocks)} blocks, {'OK' if not errors else 'MISMATCH'}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
