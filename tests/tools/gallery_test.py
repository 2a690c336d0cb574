#!/usr/bin/python3
"""Smoke test of tools/make_gallery.py (the verification gallery, docs/verification.md).

Usage: gallery_test.py SOURCE_DIR TETHER_EXE OUT_DIR

Runs the gallery with --out OUT_DIR, --json and --quick (tether runs every case; ccx every case
it runs in the full regeneration but the two long frictional ones, Cattaneo-Mindlin and ironing,
which take it 25-30 s each, up to ~2 min on a loaded machine), then checks that the markdown has
every section and figure, that every tether error in the JSON is within the tolerance stated for its case (and the same
number is in the markdown row), that the Cattaneo-Mindlin and ironing rows name the tests that
run the same decks, and, when ccx is installed, that the ccx columns are filled and within their
tolerances. Exit 0 ok, 1 failure, 77 (skip) when ccx is missing -- after the tether columns have
been produced and checked -- or when gmsh is missing (the frictional decks are meshed with it).
"""
import json
import math
import os
import shutil
import subprocess
import sys

SECTIONS = ["# Verification gallery", "## Constant-strain patch tests", "## Lamé thick cylinder under internal pressure",
            "## Cantilever under end shear (Timoshenko beam)", "## Rigid link under large rotation",
            "## Periodic RVE of a laminate", "## Contact benchmarks"]
FRICTIONAL = {"Cattaneo–Mindlin": ("tests/verification/mindlin_test.cpp", 3),
              "ironing": ("tests/verification/ironing_test.cpp", 2)}  # case prefix: test, rows
IMAGES = ["lame_profiles.png", "cantilever_convergence.png", "rigid_link.png", "hertz_2k.png", "cattaneo_mindlin.png",
          "ironing_3mm.png"]


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    source, tether, out = argv[1:]
    if not shutil.which("gmsh"):
        print("gmsh not found: the gallery cannot mesh the Cattaneo-Mindlin and ironing decks -- skipping")
        return 77
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    js = os.path.join(out, "verification.json")
    run = subprocess.run(["/usr/bin/python3", os.path.join(source, "tools", "make_gallery.py"), "--tether", tether,
                          "--out", out, "--json", js, "--quick"], capture_output=True, text=True, timeout=280)
    print(run.stdout)
    print(run.stderr, file=sys.stderr)
    problems = []
    if run.returncode != 0:
        problems.append(f"make_gallery.py exited with {run.returncode}")
    md_path = os.path.join(out, "verification.md")
    if not os.path.exists(md_path) or not os.path.exists(js):
        print("FAIL: no verification.md or JSON written", file=sys.stderr)
        return 1
    with open(md_path) as f:
        md = f.read()
    with open(js) as f:
        data = json.load(f)
    for s in SECTIONS:
        if s + "\n" not in md:
            problems.append(f"section '{s}' missing")
    for png in IMAGES:
        p = os.path.join(out, "images", "verification", png)
        if not os.path.exists(p) or os.path.getsize(p) < 1000:
            problems.append(f"figure {png} missing")
        if f"(images/verification/{png})" not in md:
            problems.append(f"figure {png} not linked")
    for name, (test, n) in FRICTIONAL.items():
        rows = [r for r in data["results"]["contact"] if r["case"].startswith(name)]
        if len(rows) != n:
            problems.append(f"{name}: {len(rows)} rows, expected {n}")
        elif test not in rows[0]["how"]:
            problems.append(f"{name}: the note does not name {test}")
        for r in rows:
            if r["ccx"] is not None or r["ccx_error"] is not None or "--quick" not in (r["ccx_note"] or ""):
                problems.append(f"{name} ({r['quantity']}): ccx ran or no note, though the gallery ran with --quick")
    counts = {key: len(rows) for key, rows in data["results"].items()}
    expected = {"patch": 10, "lame": 6, "cantilever": 9, "rigid_link": 1, "rve": 2, "contact": 10}
    if counts != expected:
        problems.append(f"row counts {counts}, expected {expected}")
    have_ccx = data["meta"]["ccx"]
    ccx_rows = 0
    for key, rows in data["results"].items():
        for r in rows:
            err, tol = r["tether_error"], r["tolerance"]
            if err is None or not math.isfinite(err) or not abs(err) <= tol:
                problems.append(f"{r['case']} ({r['quantity']}): tether error {err} beyond {tol}")
            if f"| {r['case']} |" not in md:
                problems.append(f"{r['case']}: no row in the markdown")
            if have_ccx and r["ccx_tolerance"] is not None:
                ccx_rows += 1
                e = r["ccx_error"]
                if e is None or not math.isfinite(e) or not abs(e) <= r["ccx_tolerance"]:
                    problems.append(f"{r['case']} ({r['quantity']}): ccx error {e} beyond {r['ccx_tolerance']}")
    if have_ccx and ccx_rows < 13:
        problems.append(f"ccx installed but only {ccx_rows} rows have ccx results (expected 13)")
    if problems:
        for p in problems:
            print("FAIL: " + p, file=sys.stderr)
        return 1
    print(f"gallery ok: {sum(counts.values())} tether rows within tolerance, {ccx_rows} ccx rows")
    if not have_ccx:
        print("ccx not installed: the ccx columns were not produced (tether columns checked) -- skipping")
        return 77
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
