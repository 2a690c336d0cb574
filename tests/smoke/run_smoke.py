#!/usr/bin/env python3
"""Smoke test of one deck through the `tether` program with every writer on.

Usage: run_smoke.py TETHER DECK WORK [--replace OLD=NEW]... [--restart-after-step N]

Runs `tether run DECK -o WORK/out` (a copy of DECK in WORK when --replace
edits its text, e.g. to point LIBRARY= at the plug-in the build made) and
checks, for the run to pass:
- exit status 0, and the `.sta` ends with THE ANALYSIS HAS COMPLETED SUCCESSFULLY;
- the `.dat` parses (tools/tethertools/dat.py), every value in it is finite, each
  block has the columns of its kind, and it holds every block the deck's print
  requests ask for at the last increment of each step (deck_requests.py), and
  constraint-multiplier blocks when the deck has constraints;
- the `.pvd` lists at least one `.vtu`; each exists and parses
  (tools/tethertools/vtu.py: array lengths against NumberOfPoints / NumberOfCells,
  finite values, connectivity inside the mesh, TIME as in the .pvd);
- no result file names a node or element outside the mesh: the node labels of
  the .dat's nodal and contact blocks are NodeIds of the .vtu, the element
  labels of its element blocks (and the master elements of contact state
  rows) are ElementIds;
- a deck with a *DYNAMIC step writes JOB_energy.csv (header, finite rows, the
  last at the last .vtu's time) and its plot JOB_energy.png.
With --restart-after-step N the deck (which must have *RESTART, WRITE) is also
cut before its step N+1 and run to WORK/first; the whole deck is then continued
from WORK/first/first.rst twice, with `--restart` and with `*RESTART, READ,
FILE=` in a copy of the deck: both runs get the checks above for the steps
after N, and their last displacements must equal those of the uninterrupted
run to 1e-12 relative.

Exit status 0 = OK, 1 = a check failed (the message names the deck and what).
"""
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np

import deck_requests  # next to this script
import tethertools.dat  # tools/ on PYTHONPATH (set by CTest)
import tethertools.vtu

COMPLETED = "THE ANALYSIS HAS COMPLETED SUCCESSFULLY"

# Block title -> (number of columns, column of a node label or None, column of an element label or None).
_COLUMNS = {
    "displacements": (4, 0, None), "forces": (4, 0, None), "total force": (3, None, None),
    "stresses": (8, None, 0), "strains": (8, None, 0),
    "equivalent plastic strain": (3, None, 0), "plastic strains": (8, None, 0), "actively yielding": (3, None, 0),
    "internal state variables": (None, None, 0),  # 2 + NSTATV, the same in every row
    "contact stress": (4, 0, None), "relative contact displacement": (4, 0, None),
    "contact state": (10, 0, 7), "total normal contact force": (3, None, None),
    "total shear contact force": (3, None, None), "constraint multipliers": (4, None, None),
    "velocities": (4, 0, None), "accelerations": (4, 0, None), "energies": (8, None, None),
}


class SmokeError(Exception):
    pass


def kind_of(title):
    for k in _COLUMNS:
        if title.startswith(k):
            return k
    raise SmokeError(f"unknown .dat block '{title}'")


def run_tether(tether, args, what):
    command = [tether, "run", "-q", *args]
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=300)
    except subprocess.TimeoutExpired as e:
        raise SmokeError(f"{what}: `{' '.join(command)}` did not finish in 300 s") from e
    if result.returncode != 0:
        raise SmokeError(f"{what}: `{' '.join(command)}` exited with {result.returncode}:\n"
                         f"{result.stdout}{result.stderr}")


def step_end_times(sta_path):
    """{step: total time of its last converged increment} from the .sta; checks the final line."""
    with open(sta_path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    if not lines or COMPLETED not in lines[-1]:
        raise SmokeError(f"{sta_path}: last line is {lines[-1] if lines else 'missing'!r}, not '{COMPLETED}'")
    ends = {}
    for line in lines:
        fields = line.split()
        # STEP INC ATT ITRS TOTITRS TOT-TIME ...: converged attempts have an integer ATT (cut-backs: "1U").
        if len(fields) == 9 and all(re.fullmatch(r"\d+", f) for f in fields[:5]):
            ends[int(fields[0])] = max(ends.get(int(fields[0]), -math.inf), float(fields[5]))
    if not ends:
        raise SmokeError(f"{sta_path}: no converged increment")
    return ends


def check_dat(dat_path, requests, step_ends, node_ids, element_ids):
    try:
        blocks = tethertools.dat.read(dat_path)
    except (OSError, ValueError) as e:
        raise SmokeError(f"{dat_path}: does not parse: {e}") from e
    for b in blocks:
        columns, node_col, element_col = _COLUMNS[kind_of(b["title"])]
        where = f"{dat_path}: block '{b['title']}' for set {b['set']!r} at time {b['time']}"
        if columns is None:  # a width of the deck's (SDV: 2 + NSTATV)
            columns = max(3, len(b["rows"][0]) if b["rows"] else 3)
        for row in b["rows"]:
            if len(row) != columns:
                raise SmokeError(f"{where}: row {row} has {len(row)} columns, expected {columns}")
            if not all(math.isfinite(v) for v in row):
                raise SmokeError(f"{where}: non-finite value in row {row}")
            if node_col is not None and int(row[node_col]) not in node_ids:
                raise SmokeError(f"{where}: names node {int(row[node_col])}, which is not in the mesh")
            # An open slave node of a contact state row is paired with no master element: 0.
            unpaired = {0} if kind_of(b["title"]) == "contact state" else set()
            if element_col is not None and int(row[element_col]) not in element_ids | unpaired:
                raise SmokeError(f"{where}: names element {int(row[element_col])}, which is not in the mesh")
    for step, wanted in enumerate(requests["steps"], start=1):
        if step not in step_ends:
            continue  # a restarted run prints only the steps after the restart
        time = step_ends[step]
        at_end = [b for b in blocks if abs(b["time"] - time) <= 1e-6 * max(1.0, abs(time))]
        for title, set_name in wanted:
            if not any(b["title"].startswith(title) and b["set"].upper() == set_name for b in at_end):
                raise SmokeError(f"{dat_path}: no '{title}' block for set {set_name!r} at the end of step {step} "
                                 f"(time {time})")
    if requests["constraints"] and not any(b["title"].startswith("constraint multipliers") for b in blocks):
        raise SmokeError(f"{dat_path}: the deck has constraints but the .dat has no constraint multiplier block")
    return len(blocks)


def check_output(out, job, requests):
    """All checks of one output folder; returns (vtu count, dat block count, last U array)."""
    step_ends = step_end_times(os.path.join(out, job + ".sta"))
    pvd = os.path.join(out, job + ".pvd")
    try:
        vtus = tethertools.vtu.check_collection(pvd)
    except (OSError, tethertools.vtu.VtuError) as e:
        raise SmokeError(str(e)) from e
    if not vtus:
        raise SmokeError(f"{pvd}: lists no .vtu")
    last = vtus[-1][2]
    if last["node_ids"] is None or last["element_ids"] is None:
        raise SmokeError(f"{vtus[-1][0]}: no NodeId or ElementId array")
    node_ids = {int(v) for v in last["node_ids"]}
    element_ids = {int(v) for v in last["element_ids"]} - {0}  # 0: vertex cells of element-less nodes
    if len(node_ids) != last["points"]:
        raise SmokeError(f"{vtus[-1][0]}: NodeId has repeated labels")
    n_blocks = check_dat(os.path.join(out, job + ".dat"), requests, step_ends, node_ids, element_ids)
    if requests.get("dynamic"):
        check_energy(os.path.join(out, job + "_energy.csv"), vtus[-1][1])
        for name in ("V", "A"):
            if name not in last["point_data"]:
                raise SmokeError(f"{vtus[-1][0]}: a dynamic step's .vtu has no {name} array")
    return len(vtus), n_blocks, last["point_data"].get("U")


def check_energy(path, last_time):
    """The energy history of dynamic increments: its header, finite rows, the last at the last .vtu's time."""
    header = "step,increment,time,ALLKE,ALLSE,ALLWK,ALLFD,ALLVD,ALLPD,NUMERICAL,ETOTAL"
    try:
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except OSError as e:
        raise SmokeError(f"a dynamic deck wrote no energy history: {e}") from e
    if not lines or lines[0] != header:
        raise SmokeError(f"{path}: header is not {header}")
    rows = [[float(x) for x in line.split(",")] for line in lines[1:]]
    if not rows or any(len(r) != 11 or not all(math.isfinite(x) for x in r) for r in rows):
        raise SmokeError(f"{path}: no rows, or a row without 11 finite values")
    if abs(rows[-1][2] - last_time) > 1e-9 * max(1.0, abs(last_time)):
        raise SmokeError(f"{path}: last row at time {rows[-1][2]}, the last .vtu at {last_time}")
    png = path[: -len(".csv")] + ".png"
    try:
        with open(png, "rb") as f:
            signature = f.read(8)
    except OSError as e:
        raise SmokeError(f"a dynamic deck drew no energy plot: {e}") from e
    if signature != b"\x89PNG\r\n\x1a\n" or os.path.getsize(png) < 1000:
        raise SmokeError(f"{png}: not a PNG image of a plot")


def prepare_deck(deck, work, replacements):
    """The deck to run: DECK itself, or its edited copy in WORK."""
    if not replacements:
        return os.path.abspath(deck)
    with open(deck, encoding="utf-8") as f:
        text = f.read()
    for old, new in replacements:
        if old not in text:
            raise SmokeError(f"{deck}: --replace: '{old}' does not occur in the deck")
        text = text.replace(old, new)
    copy = os.path.join(work, os.path.basename(deck))
    with open(copy, "w", encoding="utf-8") as f:
        f.write(text)
    return copy


def check_restart(tether, deck, work, split_after, requests, full_u):
    """Runs the first steps, then the rest from the restart file in both ways; checks both."""
    with open(deck, encoding="utf-8") as f:
        text = f.read()
    starts = [m.start() for m in re.finditer(r"(?im)^\*STEP\b", text)]
    if len(starts) <= split_after:
        raise SmokeError(f"{deck}: --restart-after-step {split_after}, but the deck has {len(starts)} steps")
    if not re.search(r"(?im)^\*RESTART\s*,\s*WRITE", text):
        raise SmokeError(f"{deck}: --restart-after-step needs *RESTART, WRITE in the deck")
    first = os.path.join(work, "first.inp")
    with open(first, "w", encoding="utf-8") as f:
        f.write(text[:starts[split_after]])
    run_tether(tether, [first, "-o", os.path.join(work, "first")], "restart, first steps")
    rst = os.path.join(work, "first", "first.rst")
    if not os.path.isfile(rst):
        raise SmokeError(f"*RESTART, WRITE wrote no {rst}")
    read_deck = os.path.join(work, "read.inp")
    with open(read_deck, "w", encoding="utf-8") as f:
        f.write(f"*RESTART, READ, STEP={split_after}, FILE={rst}\n" + text)
    job = os.path.splitext(os.path.basename(deck))[0]
    for args, out, name in (([deck, "--restart", rst], os.path.join(work, "resumed"), job),
                            ([read_deck], os.path.join(work, "read"), "read")):
        run_tether(tether, [*args, "-o", out], f"restart from {rst}")
        _, _, u = check_output(out, name, requests)
        if u is None or full_u is None or u.shape != full_u.shape:
            raise SmokeError(f"{out}: no displacement array U to compare with the uninterrupted run")
        scale = max(1e-300, float(np.abs(full_u).max()))
        if float(np.abs(u - full_u).max()) > 1e-12 * scale:
            raise SmokeError(f"{out}: last U differs from the uninterrupted run by {np.abs(u - full_u).max():.3e}")


def main(argv):
    args, replacements, split_after = [], [], None
    i = 1
    while i < len(argv):
        if argv[i] == "--replace" and i + 1 < len(argv):
            old, sep, new = argv[i + 1].partition("=")
            if not sep:
                print(__doc__, file=sys.stderr)
                return 2
            replacements.append((old, new))
            i += 2
        elif argv[i] == "--restart-after-step" and i + 1 < len(argv):
            split_after = int(argv[i + 1])
            i += 2
        else:
            args.append(argv[i])
            i += 1
    if len(args) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    tether, deck, work = args
    try:
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        path = prepare_deck(deck, work, replacements)
        requests = deck_requests.read(path)
        job = os.path.splitext(os.path.basename(path))[0]
        out = os.path.join(work, "out")
        run_tether(tether, [path, "-o", out], "run")
        n_vtu, n_blocks, u = check_output(out, job, requests)
        if split_after is not None:
            check_restart(tether, path, work, split_after, requests, u)
    except SmokeError as e:
        print(f"run_smoke.py: {deck}: {e}", file=sys.stderr)
        return 1
    restart = f", restart after step {split_after} OK" if split_after is not None else ""
    print(f"run_smoke.py: {os.path.basename(deck)}: exit 0, {n_vtu} .vtu, {n_blocks} .dat blocks OK{restart}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
