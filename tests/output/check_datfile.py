#!/usr/bin/env python3
"""Checks a .dat file, read with tools/tethertools/dat.py (the one .dat reader of the
tools, the examples and the tests), against an expectation.

Usage: check_datfile.py FILE.dat EXPECTED.json   (exit status 0 when the file matches)
EXPECTED.json is a list of blocks, each {"title", "set", "time"} and either
"rows" (compared with relative tolerance 1e-6 / absolute 1e-12 per value) or
"n_rows" and optionally "first_row".
"""
import json
import math
import sys

import tethertools.dat  # tools/ on PYTHONPATH (set by the caller)


def close(a, b):
    return math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-12)


def compare_rows(name, got, want):
    if len(got) != len(want):
        return [f"{name}: {len(got)} values in row, expected {len(want)}: {got}"]
    return [f"{name}: {got} != {want}"] if not all(close(g, w) for g, w in zip(got, want)) else []


def check(blocks, expected):
    errors = []
    if len(blocks) != len(expected):
        errors.append(f"{len(blocks)} blocks, expected {len(expected)}: "
                      f"{[(b['title'], b['set'], b['time']) for b in blocks]}")
    for i, (b, e) in enumerate(zip(blocks, expected)):
        name = f"block {i} ({b['title']} / {b['set']} / {b['time']})"
        if b["title"] != e["title"] or b["set"] != e["set"] or not close(b["time"], e["time"]):
            errors.append(f"{name}: expected ({e['title']} / {e['set']} / {e['time']})")
            continue
        if "rows" in e:
            if len(b["rows"]) != len(e["rows"]):
                errors.append(f"{name}: {len(b['rows'])} rows, expected {len(e['rows'])}")
                continue
            for j, (got, want) in enumerate(zip(b["rows"], e["rows"])):
                errors += compare_rows(f"{name} row {j}", got, want)
        else:
            if len(b["rows"]) != e["n_rows"]:
                errors.append(f"{name}: {len(b['rows'])} rows, expected {e['n_rows']}")
            elif "first_row" in e:
                errors += compare_rows(f"{name} first row", b["rows"][0], e["first_row"])
    return errors


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    blocks = tethertools.dat.read(argv[1])
    with open(argv[2], encoding="utf-8") as f:
        expected = json.load(f)
    errors = check(blocks, expected)
    for e in errors:
        print("check_datfile.py:", e, file=sys.stderr)
    print(f"check_datfile.py: {argv[1]}: {len(blocks)} blocks, {'OK' if not errors else 'MISMATCH'}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
