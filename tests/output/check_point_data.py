#!/usr/bin/env python3
"""Reads one .vtu with meshio and compares some of its point-data arrays.

Usage: check_point_data.py FILE.vtu EXPECTED.json
EXPECTED.json: {"NAME": [values per node] or [[components] per node], ...};
a name mapped to null must be absent. Values are compared to 1e-12 relative
(absolute 1e-300). Exit status 0 when everything matches, 1 otherwise,
3 when meshio is not installed.
"""
import json
import sys

try:
    import meshio
    import numpy as np
except ImportError:
    sys.exit(3)


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    mesh = meshio.read(argv[1])
    with open(argv[2], encoding="utf-8") as f:
        expected = json.load(f)
    errors = []
    for name, want in expected.items():
        if want is None:
            if name in mesh.point_data:
                errors.append(f"{name}: present, expected absent")
            continue
        if name not in mesh.point_data:
            errors.append(f"{name}: missing (have {sorted(mesh.point_data)})")
            continue
        got = np.asarray(mesh.point_data[name], dtype=float)
        want = np.asarray(want, dtype=float)
        if got.shape != want.shape:
            errors.append(f"{name}: shape {got.shape}, expected {want.shape}")
        elif not np.allclose(got, want, rtol=1e-12, atol=1e-300):
            worst = np.unravel_index(np.argmax(np.abs(got - want)), got.shape)
            errors.append(f"{name}: mismatch at {worst}: {got[worst]} != {want[worst]}")
    for e in errors:
        print("check_point_data.py:", e, file=sys.stderr)
    print(f"check_point_data.py: {argv[1]}: {len(expected)} arrays, {'OK' if not errors else 'MISMATCH'}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
