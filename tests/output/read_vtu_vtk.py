#!/usr/bin/env python3
"""Check tether's .vtu files with VTK's own XML reader (the one ParaView uses).

Usage: read_vtu_vtk.py JOB.pvd EXPECTED.json   (same EXPECTED.json as read_vtu.py)
Exit status 0 when every listed .vtu matches, 1 otherwise, 3 when the Python
VTK module (Debian python3-vtk9) is not installed.
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

try:
    import numpy as np
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
except ImportError:
    sys.exit(3)

VTK_TYPES = {"triangle": 5, "quad": 9, "triangle6": 22, "quad8": 23}


def fail(message):
    print("read_vtu_vtk.py:", message, file=sys.stderr)
    sys.exit(1)


def expect_close(name, got, want):
    got, want = np.asarray(got, dtype=float), np.asarray(want, dtype=float)
    if got.shape != want.shape or not np.allclose(got, want, rtol=1e-14, atol=1e-300):
        fail(f"{name}: {got.tolist()} != {want.tolist()}")


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    with open(argv[2], encoding="utf-8") as f:
        expected = json.load(f)
    directory = os.path.dirname(os.path.abspath(argv[1]))
    files = [d.get("file") for d in ET.parse(argv[1]).getroot().findall("./Collection/DataSet")]
    if files != [i["file"] for i in expected["increments"]]:
        fail(f"{argv[1]} lists {files}")
    for inc in expected["increments"]:
        path = os.path.join(directory, inc["file"])
        errors = vtk.vtkStringOutputWindow()
        vtk.vtkOutputWindow.SetInstance(errors)
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        if reader.GetErrorCode() != 0 or "ERROR" in errors.GetOutput():
            fail(f"{path}: VTK reader error: {errors.GetOutput()}")
        grid = reader.GetOutput()
        expect_close(f"{path}: points", vtk_to_numpy(grid.GetPoints().GetData()), expected["points"])
        types = [grid.GetCellType(i) for i in range(grid.GetNumberOfCells())]
        if types != [VTK_TYPES[c["type"]] for c in expected["cells"]]:
            fail(f"{path}: cell types {types}")
        for i, cell in enumerate(expected["cells"]):
            ids = grid.GetCell(i).GetPointIds()
            if [ids.GetId(k) for k in range(ids.GetNumberOfIds())] != cell["nodes"]:
                fail(f"{path}: connectivity of cell {i}")
        point_data = grid.GetPointData()
        for name in ("U", "RF", "S", "E", "S_Mises", "LAGRANGE_MULTIPLIER", "CONSTRAINT_FORCE"):
            expect_close(f"{path}: {name}", vtk_to_numpy(point_data.GetArray(name)), inc[name])
        expect_close(f"{path}: cell S", vtk_to_numpy(grid.GetCellData().GetArray("S")), inc["cell_S"])
        expect_close(f"{path}: TIME", vtk_to_numpy(grid.GetFieldData().GetArray("TIME")), [inc["time"]])
    print(f"read_vtu_vtk.py: {argv[1]}: {len(files)} datasets OK")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
