"""Reader and checker of VTK XML files (.pvd collections, .vtu unstructured grids)
with the standard library and NumPy only, for the smoke tier.

Data arrays may be `ascii`, inline `binary` (base64 of a UInt32/UInt64 byte
count followed by the values) or `appended` (`raw` or `base64` AppendedData),
little or big endian. Compressed data (a `compressor` attribute) is refused:
tether does not write it.

check_vtu(path) returns a dict with the piece's sizes, the NodeId and
ElementId arrays and the TIME field, and raises VtuError naming the file and
the array for anything malformed: array lengths that do not match
NumberOfPoints / NumberOfCells times NumberOfComponents, non-finite values,
connectivity naming a point outside the mesh, offsets or cell types that do
not fit the connectivity.
"""
import base64
import os
import xml.etree.ElementTree as ET

import numpy as np


class VtuError(Exception):
    pass


_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4", "UInt32": "u4",
          "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8"}

# VTK cell type -> number of points (the linear and quadratic 2D cells tether writes, and lines).
_CELL_POINTS = {1: 1, 3: 2, 5: 3, 9: 4, 21: 3, 22: 6, 23: 8}


def read_pvd(path):
    """[(file, timestep)] of a .pvd collection, files relative to its folder."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise VtuError(f"{path}: not XML: {e}") from e
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        raise VtuError(f"{path}: not a VTK Collection")
    out = []
    for d in root.findall("./Collection/DataSet"):
        if d.get("file") is None or d.get("timestep") is None:
            raise VtuError(f"{path}: DataSet without file or timestep")
        out.append((d.get("file"), float(d.get("timestep"))))
    return out


def _split_appended(data):
    """(xml bytes with the raw appended block removed, raw bytes after '_' or None)."""
    start = data.find(b"<AppendedData")
    if start < 0:
        return data, None
    underscore = data.find(b"_", data.find(b">", start))
    end = data.rfind(b"</AppendedData>")
    if underscore < 0 or end < underscore:
        raise VtuError("AppendedData without '_' marker or end tag")
    return data[:underscore] + data[end:], data[underscore + 1:end]


class _Decoder:
    def __init__(self, root, appended_raw, appended_encoding):
        self.order = "<" if root.get("byte_order", "LittleEndian") == "LittleEndian" else ">"
        self.header = np.dtype(self.order + ("u8" if root.get("header_type", "UInt32") == "UInt64" else "u4"))
        if root.get("compressor"):
            raise VtuError(f"compressed data ({root.get('compressor')}) is not supported by this reader")
        self.appended = appended_raw
        if appended_raw is not None and appended_encoding == "base64":
            self.appended_text = appended_raw.strip()

    def _counted(self, raw, dtype, what):
        if len(raw) < self.header.itemsize:
            raise VtuError(f"{what}: data shorter than its byte-count header")
        nbytes = int(np.frombuffer(raw[:self.header.itemsize], self.header)[0])
        body = raw[self.header.itemsize:self.header.itemsize + nbytes]
        if len(body) != nbytes or nbytes % dtype.itemsize:
            raise VtuError(f"{what}: header says {nbytes} bytes, {len(body)} present ({dtype} values)")
        return np.frombuffer(body, dtype)

    def decode(self, array):
        name = array.get("Name", "?")
        if array.get("type") not in _TYPES:
            raise VtuError(f"array {name}: unknown type {array.get('type')}")
        dtype = np.dtype(self.order + _TYPES[array.get("type")])
        fmt = array.get("format", "ascii")
        if fmt == "ascii":
            text = (array.text or "").split()
            try:
                values = np.array([float(t) for t in text], dtype=np.float64)
            except ValueError as e:
                raise VtuError(f"array {name}: bad ascii value: {e}") from e
            return values if dtype.kind == "f" else values.astype(dtype)
        if fmt == "binary":
            try:
                raw = base64.b64decode("".join((array.text or "").split()), validate=True)
            except ValueError as e:
                raise VtuError(f"array {name}: bad base64: {e}") from e
            return self._counted(raw, dtype, f"array {name}")
        if fmt == "appended":
            if self.appended is None:
                raise VtuError(f"array {name}: format=appended but the file has no AppendedData")
            offset = int(array.get("offset", "0"))
            if hasattr(self, "appended_text"):
                # base64 appended data: each array is its own base64 run starting at `offset` characters.
                text = self.appended_text.decode("ascii")[offset:]
                head_chars = 4 * ((self.header.itemsize + 2) // 3)
                head = base64.b64decode(text[:head_chars])
                nbytes = int(np.frombuffer(head[:self.header.itemsize], self.header)[0])
                chars = 4 * ((self.header.itemsize + nbytes + 2) // 3)
                return self._counted(base64.b64decode(text[:chars]), dtype, f"array {name}")
            return self._counted(self.appended[offset:], dtype, f"array {name}")
        raise VtuError(f"array {name}: unknown format {fmt}")


def _finite(values, what):
    if values.dtype.kind == "f" and not np.all(np.isfinite(values)):
        bad = int(np.flatnonzero(~np.isfinite(values))[0])
        raise VtuError(f"{what}: non-finite value {values[bad]} at position {bad}")


def _sized(decoder, array, count, what):
    values = decoder.decode(array)
    components = int(array.get("NumberOfComponents", "1"))
    if values.size != components * count:
        raise VtuError(f"{what} {array.get('Name')}: {values.size} values, expected {components} x {count}")
    _finite(values, f"{what} {array.get('Name')}")
    return values


def _check_cells(decoder, cells, n_points, n_cells):
    arrays = {a.get("Name"): a for a in cells.findall("DataArray")}
    for name in ("connectivity", "offsets", "types"):
        if name not in arrays:
            raise VtuError(f"Cells: no {name} array")
    connectivity = decoder.decode(arrays["connectivity"]).astype(np.int64)
    offsets = decoder.decode(arrays["offsets"]).astype(np.int64)
    types = decoder.decode(arrays["types"]).astype(np.int64)
    if offsets.size != n_cells or types.size != n_cells:
        raise VtuError(f"Cells: {offsets.size} offsets and {types.size} types for {n_cells} cells")
    if connectivity.size and (connectivity.min() < 0 or connectivity.max() >= n_points):
        bad = int(connectivity[(connectivity < 0) | (connectivity >= n_points)][0])
        raise VtuError(f"Cells: connectivity names point {bad} outside the mesh ({n_points} points)")
    sizes = np.diff(np.concatenate([[0], offsets]))
    if n_cells and (np.any(sizes <= 0) or offsets[-1] != connectivity.size):
        raise VtuError(f"Cells: offsets do not partition the {connectivity.size} connectivity entries")
    for t, s in zip(types, sizes):
        if int(t) not in _CELL_POINTS:
            raise VtuError(f"Cells: unexpected VTK cell type {t}")
        if _CELL_POINTS[int(t)] != s:
            raise VtuError(f"Cells: a type-{t} cell with {s} points (expected {_CELL_POINTS[int(t)]})")


def check_vtu(path):
    """Parses and checks one .vtu; returns {points, cells, node_ids, element_ids, time, point_data, cell_data}."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise VtuError(f"{path}: {e}") from e
    try:
        xml_bytes, raw = _split_appended(data)
        root = ET.fromstring(xml_bytes)
    except (VtuError, ET.ParseError) as e:
        raise VtuError(f"{path}: not a readable VTK XML file: {e}") from e
    if root.tag != "VTKFile" or root.get("type") != "UnstructuredGrid":
        raise VtuError(f"{path}: not a VTK UnstructuredGrid file")
    appended = root.find("AppendedData")
    try:
        decoder = _Decoder(root, raw, appended.get("encoding", "raw") if appended is not None else None)
        pieces = root.findall("./UnstructuredGrid/Piece")
        if len(pieces) != 1:
            raise VtuError(f"{len(pieces)} pieces, expected 1")
        piece = pieces[0]
        n_points, n_cells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))
        out = {"points": n_points, "cells": n_cells, "time": None, "point_data": {}, "cell_data": {}}
        for a in root.findall("./UnstructuredGrid/FieldData/DataArray"):
            values = decoder.decode(a)
            if values.size != int(a.get("NumberOfTuples", "1")) * int(a.get("NumberOfComponents", "1")):
                raise VtuError(f"field {a.get('Name')}: {values.size} values, NumberOfTuples {a.get('NumberOfTuples')}")
            _finite(values, f"field {a.get('Name')}")
            if a.get("Name") == "TIME":
                out["time"] = float(values[0])
        for a in piece.findall("./PointData/DataArray"):
            out["point_data"][a.get("Name")] = _sized(decoder, a, n_points, "point data")
        for a in piece.findall("./CellData/DataArray"):
            out["cell_data"][a.get("Name")] = _sized(decoder, a, n_cells, "cell data")
        points = piece.find("./Points/DataArray")
        if points is None:
            raise VtuError("no Points")
        _sized(decoder, points, n_points, "Points")
        cells = piece.find("Cells")
        if cells is None:
            raise VtuError("no Cells")
        _check_cells(decoder, cells, n_points, n_cells)
    except VtuError as e:
        raise VtuError(f"{path}: {e}") from e
    out["node_ids"] = out["point_data"].get("NodeId")
    out["element_ids"] = out["cell_data"].get("ElementId")
    return out


def check_collection(pvd):
    """Checks the .pvd and every .vtu it lists; returns [(file, timestep, check_vtu result)]."""
    listed = read_pvd(pvd)
    folder = os.path.dirname(os.path.abspath(pvd))
    out = []
    previous = -np.inf
    for file, timestep in listed:
        if timestep < previous:
            raise VtuError(f"{pvd}: timesteps decrease at {file}")
        previous = timestep
        path = os.path.join(folder, file)
        if not os.path.isfile(path):
            raise VtuError(f"{pvd}: lists {file}, which does not exist")
        result = check_vtu(path)
        if result["time"] is not None and abs(result["time"] - timestep) > 1e-9 * max(1.0, abs(timestep)):
            raise VtuError(f"{path}: TIME {result['time']} but the .pvd says {timestep}")
        out.append((file, timestep, result))
    return out
