#!/usr/bin/env python3
"""Fails when a deck in EXAMPLES/*/*.inp is not in the smoke tier's list.

Usage: check_examples_listed.py EXAMPLES_DIR LISTED...   (LISTED: `folder/stem`, as in
tests/smoke/CMakeLists.txt). Exit status 0 when every example deck is listed and
every listed deck exists.
"""
import glob
import os
import sys


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    root, listed = argv[1], set(argv[2:])
    on_disk = {os.path.relpath(p, root)[:-len(".inp")] for p in glob.glob(os.path.join(root, "*", "*.inp"))}
    missing, stale = sorted(on_disk - listed), sorted(listed - on_disk)
    for m in missing:
        print(f"check_examples_listed.py: examples/{m}.inp is not run by the smoke tier: add it to "
              "tests/smoke/CMakeLists.txt", file=sys.stderr)
    for s in stale:
        print(f"check_examples_listed.py: tests/smoke/CMakeLists.txt lists examples/{s}.inp, which does not exist",
              file=sys.stderr)
    if not missing and not stale:
        print(f"check_examples_listed.py: all {len(on_disk)} example decks are in the smoke tier")
    return 1 if missing or stale else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
