#!/usr/bin/env python3
"""Independent checks of tether's constraint-multiplier output.

Usage:
  check_multiplier_output.py dat FILE.dat EXPECTED.json
      EXPECTED.json: {"time": t, "blocks": {"SET": [[constraint, equation, f, lambda], ...], ...}}.
      Reads FILE.dat with tools/tethertools/dat.py and compares the last
      `constraint multipliers` block of each SET at that time (rel 1e-6, abs 1e-12,
      the precision of E13.6).
  check_multiplier_output.py rigid-link JOB_DIR JOB P
      The rigid link run (examples/rigid_link/rigid_link.inp): for every increment,
      lambda from the .dat = P / sin(theta) with theta from the printed displacement
      of B, and in the last .vtu (read with meshio) CONSTRAINT_FORCE at A = -RF at A,
      CONSTRAINT_FORCE at B = -lambda * (unit vector A->B), LAGRANGE_MULTIPLIER = lambda
      at A and B.
Exit status 0 when everything matches, 1 otherwise.
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ET

import tethertools.dat  # tools/ on PYTHONPATH (set by the caller)

TITLE = "constraint multipliers (constraint,equation,f,lambda)"


def fail(message):
    print("check_multiplier_output.py:", message, file=sys.stderr)
    sys.exit(1)


def close(a, b, rel=1e-6, abs_=1e-12):
    return math.isclose(a, b, rel_tol=rel, abs_tol=abs_)


def check_dat(path, expected_path):
    with open(expected_path, encoding="utf-8") as f:
        expected = json.load(f)
    blocks = tethertools.dat.read(path)
    for set_name, rows in expected["blocks"].items():
        block = tethertools.dat.last_block(blocks, TITLE, set_name)
        if block["title"] != TITLE:
            fail(f"title {block['title']!r}")
        if not close(block["time"], expected["time"]):
            fail(f"{set_name}: time {block['time']} != {expected['time']}")
        if len(block["rows"]) != len(rows):
            fail(f"{set_name}: {len(block['rows'])} rows, expected {len(rows)}")
        for got, want in zip(block["rows"], rows):
            if len(got) != len(want) or not all(close(g, w) for g, w in zip(got, want)):
                fail(f"{set_name}: row {got} != {want}")
    print(f"check_multiplier_output.py: {path}: {len(expected['blocks'])} multiplier blocks OK")


def check_rigid_link(directory, job, load):
    import meshio
    import numpy as np

    blocks = tethertools.dat.read(os.path.join(directory, job + ".dat"))
    displacements = [b for b in blocks if b["title"].startswith("displacements") and b["set"] == "B"]
    multipliers = [b for b in blocks if b["title"] == TITLE and b["set"] == "LINK"]
    if not displacements or len(displacements) != len(multipliers):
        fail(f"{len(displacements)} displacement blocks of B, {len(multipliers)} LINK multiplier blocks")
    x_b0 = np.array([0.34729635533386083, -1.969615506024416])
    worst = 0.0
    for d, m in zip(displacements, multipliers):
        x_b = x_b0 + np.array(d["rows"][0][1:3])
        theta = math.atan2(-x_b[1], x_b[0])
        lam = m["rows"][0][3]
        worst = max(worst, abs(lam / (load / math.sin(theta)) - 1))
        if abs(m["rows"][0][2]) > 1e-9:
            fail(f"time {m['time']}: f = {m['rows'][0][2]}")
    if worst > 1e-6:  # E13.6 in the .dat
        fail(f"lambda differs from P / sin(theta) by {worst:.2e} (relative)")

    root = ET.parse(os.path.join(directory, job + ".pvd")).getroot()
    last = root.findall("./Collection/DataSet")[-1].get("file")
    mesh = meshio.read(os.path.join(directory, last))
    ids = list(mesh.point_data["NodeId"].astype(int))
    a, b = ids.index(1), ids.index(2)
    force = mesh.point_data["CONSTRAINT_FORCE"]
    rf = mesh.point_data["RF"]
    u = mesh.point_data["U"]
    lam = multipliers[-1]["rows"][0][3]
    if not np.allclose(force[a], -rf[a], rtol=1e-12, atol=1e-12):
        fail(f"CONSTRAINT_FORCE at A {force[a]} != -RF at A {-rf[a]}")
    x = mesh.points[:, :2] + u[:, :2]
    n = (x[b] - x[a]) / np.linalg.norm(x[b] - x[a])
    if not np.allclose(force[b][:2], -lam * n, rtol=1e-6, atol=1e-9):
        fail(f"CONSTRAINT_FORCE at B {force[b]} != -lambda n {-lam * n}")
    multiplier = mesh.point_data["LAGRANGE_MULTIPLIER"]
    if not (close(multiplier[a], lam) and close(multiplier[b], lam)):
        fail(f"LAGRANGE_MULTIPLIER {multiplier[a]}, {multiplier[b]} != {lam}")
    print(f"check_multiplier_output.py: rigid link: {len(multipliers)} increments, "
          f"max relative error of lambda {worst:.1e}; VTU constraint force = -RF at A")


def main(argv):
    if len(argv) == 4 and argv[1] == "dat":
        check_dat(argv[2], argv[3])
        return 0
    if len(argv) == 5 and argv[1] == "rigid-link":
        check_rigid_link(argv[2], argv[3], float(argv[4]))
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
