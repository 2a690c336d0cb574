#!/usr/bin/env python3
"""Independent check of tether's ParaView output with meshio.

Usage: read_vtu.py JOB.pvd EXPECTED.json

Reads the .pvd collection with xml.etree and every .vtu it lists with meshio,
and compares them with EXPECTED.json, written by the C++ test:
  {"points": [[x, y, z], ...], "node_ids": [...],
   "cells": [{"type": "quad", "nodes": [...], "id": 101}, ...],
   "increments": [{"file": "job_1_1.vtu", "time": t,
                   "U": [[...]], "RF": [[...]], "S": [[6 values]], "E": [[...]],
                   "S_Mises": [...], "cell_S": [[6 values]], "LAGRANGE_MULTIPLIER": [...],
                   "CONSTRAINT_FORCE": [[fx, fy, 0]]}]}
Exit status 0 when everything matches, 1 otherwise.
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np


def fail(message):
    print("read_vtu.py:", message, file=sys.stderr)
    sys.exit(1)


def expect_close(name, got, want):
    got = np.asarray(got, dtype=float)
    want = np.asarray(want, dtype=float)
    if got.shape != want.shape:
        fail(f"{name}: shape {got.shape}, expected {want.shape}")
    if not np.allclose(got, want, rtol=1e-14, atol=1e-300):
        worst = np.unravel_index(np.argmax(np.abs(got - want)), got.shape)
        fail(f"{name}: mismatch at {worst}: {got[worst]} != {want[worst]}")


def concatenated_cell_data(mesh, name):
    if name not in mesh.cell_data:
        fail(f"cell data {name} missing (have {sorted(mesh.cell_data)})")
    return np.concatenate([np.asarray(block) for block in mesh.cell_data[name]])


def check_vtu(path, expected, inc):
    mesh = meshio.read(path)
    expect_close(f"{path}: points", mesh.points, expected["points"])
    # Cells, in element order (meshio groups consecutive cells of one type).
    types, connectivity = [], []
    for block in mesh.cells:
        for row in block.data:
            types.append(block.type)
            connectivity.append([int(n) for n in row])
    want_types = [c["type"] for c in expected["cells"]]
    want_nodes = [c["nodes"] for c in expected["cells"]]
    if types != want_types:
        fail(f"{path}: cell types {types}, expected {want_types}")
    if connectivity != want_nodes:
        fail(f"{path}: connectivity {connectivity}, expected {want_nodes}")
    expect_close(f"{path}: ElementId", concatenated_cell_data(mesh, "ElementId"),
                 [c["id"] for c in expected["cells"]])
    expect_close(f"{path}: cell S", concatenated_cell_data(mesh, "S"), inc["cell_S"])
    expect_close(f"{path}: NodeId", mesh.point_data["NodeId"], expected["node_ids"])
    for name in ("U", "RF", "S", "E", "S_Mises", "LAGRANGE_MULTIPLIER", "CONSTRAINT_FORCE"):
        if name not in inc:
            if name in mesh.point_data:
                fail(f"{path}: unexpected point data {name}")
            continue
        if name not in mesh.point_data:
            fail(f"{path}: point data {name} missing (have {sorted(mesh.point_data)})")
        expect_close(f"{path}: {name}", mesh.point_data[name], inc[name])
    time = np.asarray(mesh.field_data.get("TIME", [np.nan])).ravel()
    expect_close(f"{path}: TIME", time, [inc["time"]])


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    pvd, expected_path = argv[1], argv[2]
    with open(expected_path, encoding="utf-8") as f:
        expected = json.load(f)
    root = ET.parse(pvd).getroot()
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        fail(f"{pvd}: not a VTK Collection")
    datasets = root.findall("./Collection/DataSet")
    listed = [(d.get("file"), float(d.get("timestep"))) for d in datasets]
    wanted = [(i["file"], i["time"]) for i in expected["increments"]]
    if listed != wanted:
        fail(f"{pvd}: lists {listed}, expected {wanted}")
    directory = os.path.dirname(os.path.abspath(pvd))
    for inc in expected["increments"]:
        check_vtu(os.path.join(directory, inc["file"]), expected, inc)
    print(f"read_vtu.py: {pvd}: {len(datasets)} datasets OK")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
