#!/usr/bin/env python3
"""The smoke runner's checks fail on broken output, and read every VTU encoding.

Usage: runner_test.py TETHER DECK WORK

Runs DECK (which must print U, S and a TOTALS=YES or ONLY RF) through run_smoke.py,
which must pass; then breaks copies of its output one way at a time and
requires the runner's checks to reject each with a message naming the fault:
a connectivity entry past NumberOfPoints, a NumberOfPoints that does not match
the arrays, a NaN in U, a .pvd naming a missing .vtu, a .dat row naming a node
or an element outside the mesh, a requested .dat block left out, a .sta without the
completion line. It also re-encodes the last .vtu as ascii, raw appended and
base64 appended data (tether writes inline base64; `tether run --ascii`
writes ascii) and requires the reader to return the same arrays.
Exit status 0 = OK, 1 = a check let a fault pass or rejected good output.
"""
import base64
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np

import deck_requests  # next to this script
import run_smoke
import tethertools.vtu as vtu_reader  # tools/ on PYTHONPATH (set by CTest)

failures = []


def expect_error(what, words, check):
    try:
        check()
    except (run_smoke.SmokeError, vtu_reader.VtuError) as e:
        if words not in str(e):
            failures.append(f"{what}: rejected, but the message does not say '{words}': {e}")
        else:
            print(f"runner_test.py: {what}: detected ({e})")
        return
    failures.append(f"{what}: not detected")


def decoded_arrays(path):
    """(xml root, {DataArray element: values}) of an inline-encoded .vtu."""
    root = ET.parse(path).getroot()
    decoder = vtu_reader._Decoder(root, None, None)
    return root, {a: decoder.decode(a) for a in root.iter("DataArray")}


def write_encoded(root, arrays, path, encoding):
    """Writes the .vtu with every array in `encoding`: ascii, raw (appended) or base64 (appended)."""
    blobs, offset = [], 0
    for a, values in arrays.items():
        for key in ("offset", "format"):
            a.attrib.pop(key, None)
        if encoding == "ascii":
            a.set("format", "ascii")
            a.text = " ".join(repr(v.item()) for v in values)
            continue
        data = np.ascontiguousarray(values).tobytes()
        blob = np.array([len(data)], dtype="<u8").tobytes() + data
        if encoding == "base64":
            blob = base64.b64encode(blob)
        a.set("format", "appended")
        a.set("offset", str(offset))
        a.text = None
        blobs.append(blob)
        offset += len(blob)
    text = ET.tostring(root)
    if encoding != "ascii":
        closing = b"</VTKFile>"
        text = text[:text.rfind(closing)] + f'<AppendedData encoding="{encoding}">_'.encode() + b"".join(
            blobs) + b"</AppendedData>" + closing
    with open(path, "wb") as f:
        f.write(text)


def check_encodings(vtu, scratch):
    good = vtu_reader.check_vtu(vtu)
    for encoding in ("ascii", "raw", "base64"):
        root, arrays = decoded_arrays(vtu)
        path = os.path.join(scratch, f"{encoding}.vtu")
        write_encoded(root, arrays, path, encoding)
        try:
            again = vtu_reader.check_vtu(path)
        except vtu_reader.VtuError as e:
            failures.append(f"{encoding} encoding: good file rejected: {e}")
            continue
        for name, values in good["point_data"].items():
            if not np.array_equal(values, again["point_data"][name]):
                failures.append(f"{encoding} encoding: point data {name} reads back differently")


def broken_vtu(vtu, scratch, name, change):
    root, arrays = decoded_arrays(vtu)
    change(root, arrays)
    path = os.path.join(scratch, name + ".vtu")
    write_encoded(root, arrays, path, "ascii")
    return path


def named(arrays, name):
    return next(a for a in arrays if a.get("Name") == name)


def break_connectivity(root, arrays):
    n = int(root.find("./UnstructuredGrid/Piece").get("NumberOfPoints"))
    arrays[named(arrays, "connectivity")] = arrays[named(arrays, "connectivity")].copy()
    arrays[named(arrays, "connectivity")][0] = n


def break_point_count(root, arrays):
    piece = root.find("./UnstructuredGrid/Piece")
    piece.set("NumberOfPoints", str(int(piece.get("NumberOfPoints")) + 1))


def break_displacement(root, arrays):
    u = arrays[named(arrays, "U")].copy()
    u[1] = np.nan
    arrays[named(arrays, "U")] = u


def edited_copy(out, scratch, name, edit):
    """A copy of the output folder with edit(folder) applied."""
    copy = os.path.join(scratch, name)
    shutil.copytree(out, copy)
    edit(copy)
    return copy


def replace_in(path, old, new):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if old not in text:
        failures.append(f"test setup: '{old}' not in {path}")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(old, new, 1))


def relabel_first_row(path, title, label):
    """Gives the first row of the first block whose header starts with `title` the label `label`."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    start = text.find("\n" + title)
    if start < 0:
        failures.append(f"test setup: no '{title}' block in {path}")
        return
    row = text.find("\n\n", start + 1) + 2  # the first row, after the header's blank line
    with open(path, "w", encoding="utf-8") as f:
        f.write(text[:row] + f"{label:10d}" + text[row + 10:])


def remove_last_block(path, title):
    """Removes the last block whose header starts with `title` (header, blank line, rows)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    start = text.rfind("\n" + title)
    if start < 0:
        failures.append(f"test setup: no '{title}' block in {path}")
        return
    rows = text.find("\n\n", start + 1) + 2  # past the header and its blank line
    end = text.find("\n\n", rows)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text[:start] + (text[end:] if end >= 0 else "\n"))


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    tether, deck, work = argv[1:]
    shutil.rmtree(work, ignore_errors=True)
    good_dir = os.path.join(work, "good")
    if run_smoke.main(["run_smoke.py", tether, deck, good_dir]) != 0:
        print("runner_test.py: the runner rejected good output", file=sys.stderr)
        return 1
    job = os.path.splitext(os.path.basename(deck))[0]
    out = os.path.join(good_dir, "out")
    requests = deck_requests.read(deck)
    scratch = os.path.join(work, "scratch")
    os.makedirs(scratch)
    last_vtu = os.path.join(out, vtu_reader.read_pvd(os.path.join(out, job + ".pvd"))[-1][0])

    check_encodings(last_vtu, scratch)
    expect_error("connectivity past the points", "outside the mesh",
                 lambda: vtu_reader.check_vtu(broken_vtu(last_vtu, scratch, "connectivity", break_connectivity)))
    expect_error("NumberOfPoints one too many", "expected",
                 lambda: vtu_reader.check_vtu(broken_vtu(last_vtu, scratch, "points", break_point_count)))
    expect_error("NaN displacement", "non-finite",
                 lambda: vtu_reader.check_vtu(broken_vtu(last_vtu, scratch, "nan", break_displacement)))

    missing = edited_copy(out, scratch, "missing_vtu", lambda d: os.remove(os.path.join(d, os.path.basename(last_vtu))))
    expect_error(".pvd naming a missing .vtu", "does not exist", lambda: run_smoke.check_output(missing, job, requests))
    stranger = edited_copy(out, scratch, "stranger", lambda d: relabel_first_row(os.path.join(d, job + ".dat"),
                                                                                 " displacements", 99999))
    expect_error(".dat row naming node 99999", "node 99999", lambda: run_smoke.check_output(stranger, job, requests))
    foreign = edited_copy(out, scratch, "foreign", lambda d: relabel_first_row(os.path.join(d, job + ".dat"),
                                                                               " stresses", 88888))
    expect_error(".dat row naming element 88888", "element 88888", lambda: run_smoke.check_output(foreign, job, requests))
    no_totals = edited_copy(out, scratch, "no_totals", lambda d: remove_last_block(os.path.join(d, job + ".dat"),
                                                                                  " total force (fx,fy,fz)"))
    expect_error("a requested block left out", "no 'total force' block",
                 lambda: run_smoke.check_output(no_totals, job, requests))
    unfinished = edited_copy(out, scratch, "unfinished", lambda d: replace_in(
        os.path.join(d, job + ".sta"), run_smoke.COMPLETED, "THE ANALYSIS HAS NOT BEEN COMPLETED"))
    expect_error(".sta without the completion line", "last line",
                 lambda: run_smoke.check_output(unfinished, job, requests))

    # tether's own ascii output reads too.
    ascii_out = os.path.join(work, "ascii")
    subprocess.run([tether, "run", "-q", "--ascii", deck, "-o", ascii_out], check=True, timeout=300)
    try:
        run_smoke.check_output(ascii_out, job, requests)
    except (run_smoke.SmokeError, vtu_reader.VtuError) as e:
        failures.append(f"tether --ascii output rejected: {e}")

    for f in failures:
        print("runner_test.py:", f, file=sys.stderr)
    print(f"runner_test.py: {'OK' if not failures else f'{len(failures)} failures'}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
