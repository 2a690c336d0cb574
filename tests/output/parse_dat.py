#!/usr/bin/env python3
"""Reader for the block layout of CalculiX .dat files, which tether's .dat follows.

A block is a header line `<title> for set <SET> and time <T>` (older ccx writes
`forset` in the strain header) followed by rows of whitespace-separated
numbers; blank lines are ignored. Fortran `D` exponents are accepted. Contact
headers `... for all contact elements and time T`, `... for time T` (set "")
and tether's `... for pair NAME and time T` (set NAME) are blocks too.

Usage: parse_dat.py FILE.dat EXPECTED.json
EXPECTED.json is a list of blocks, each {"title", "set", "time"} and either
"rows" (compared with relative tolerance 1e-6 / absolute 1e-12 per value) or
"n_rows" and optionally "first_row". Exit status 0 when the file matches.
"""
import json
import math
import re
import sys

HEADER = re.compile(r"^\s*(?P<title>\S.*?)\s+for\s*set\s+(?P<set>\S+)\s+and\s+time\s+(?P<time>\S+)\s*$")
# Contact blocks: ccx's "... for all contact elements and time T" ("forall" in the
# CELS header) and "... for time T" (set ""), tether's "... for pair NAME and time T".
CONTACT_HEADER = re.compile(
    r"^\s*(?P<title>\S.*?)\s*\bfor\s*(?:pair\s+(?P<set>\S+)\s+and\s+|all\s+contact\s+elements\s+and\s+)?"
    r"time\s*(?P<time>[-+0-9.]\S*)\s*$")


def to_float(token):
    return float(token.replace("D", "E").replace("d", "e"))


def parse(text):
    """List of blocks {title, set, time, rows}; rows are lists of floats."""
    blocks = []
    current = None
    for number, line in enumerate(text.splitlines(), start=1):
        if not line.strip():
            continue
        header = HEADER.match(line) or CONTACT_HEADER.match(line)
        if header:
            current = {
                "title": header["title"],
                "set": header["set"] or "",
                "time": to_float(header["time"]),
                "rows": [],
            }
            blocks.append(current)
            continue
        if current is None:
            raise ValueError(f"line {number}: data before any block header: {line!r}")
        try:
            current["rows"].append([to_float(t) for t in line.split()])
        except ValueError as error:
            raise ValueError(f"line {number}: not a header and not a numeric row: {line!r}") from error
    return blocks


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
    with open(argv[1], encoding="ascii") as f:
        blocks = parse(f.read())
    with open(argv[2], encoding="utf-8") as f:
        expected = json.load(f)
    errors = check(blocks, expected)
    for e in errors:
        print("parse_dat.py:", e, file=sys.stderr)
    print(f"parse_dat.py: {argv[1]}: {len(blocks)} blocks, {'OK' if not errors else 'MISMATCH'}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
