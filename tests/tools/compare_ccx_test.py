#!/usr/bin/python3
"""Test of tools/compare_ccx.py: usage compare_ccx_test.py SOURCE_DIR TETHER WORKDIR.

1. the Lame CPE8 verification deck agrees with ccx within the tolerances of
   docs/compare_ccx.md (exit 0), and the JSON report holds what was compared;
2. tether on a copy with Young's modulus 10 % higher: exit 1 (displacements);
3. a missing ccx: exit 2.
Exit 77 (skipped) when ccx is not installed.
"""
import json
import os
import re
import shutil
import subprocess
import sys

source, tether, work = sys.argv[1:4]
if shutil.which("ccx") is None:
    print("ccx not installed (Debian package calculix-ccx): skipped")
    sys.exit(77)
tool = os.path.join(source, "tools", "compare_ccx.py")
deck = os.path.join(source, "tests", "verification", "decks", "ccx_lame_cpe8_4x8.inp")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def run(extra, name):
    cmd = ["/usr/bin/python3", tool, deck, "--tether", tether, "--workdir", os.path.join(work, name),
           "--json", os.path.join(work, name + ".json"), "--timeout", "120"] + extra
    proc = subprocess.run(cmd, capture_output=True, text=True)
    print(f"$ {' '.join(cmd)}\n{proc.stdout}{proc.stderr}")
    return proc.returncode


def expect(cond, what):
    if not cond:
        failures.append(what)


# 1. same deck: within tolerance
rc = run(["--rtol-u", "1e-6", "--rtol-rf", "1e-6", "--rtol-s", "1e-6"], "same")
expect(rc == 0, f"same deck: exit {rc}, expected 0")
if rc == 0:
    with open(os.path.join(work, "same.json")) as f:
        report = json.load(f)
    q = report["quantities"]
    expect(q["U"]["count"] >= 300, f"too few displacements compared: {q['U']['count']}")
    expect(q["RF"]["count"] >= 10, f"too few reactions compared: {q['RF']['count']}")
    expect(q["S"]["count"] >= 1000, f"too few stresses compared: {q['S']['count']}")
    expect(report["runs"]["ccx"]["iterations"] == 1 and report["runs"]["tether"]["iterations"] == 1,
           "Newton iterations not read from the .sta files")
    expect(all(report["runs"][c]["rss_kb"] for c in ("ccx", "tether")), "peak memory not measured")

# 2. E + 10 % in tether's copy: displacements differ by ~9 %, exit 1
with open(deck) as f:
    text = f.read()
perturbed, n = re.subn(r"(\*ELASTIC\s*\n\s*)200000", r"\g<1>220000", text, flags=re.I)
expect(n == 1, "could not perturb E in the deck")
perturbed_deck = os.path.join(work, "perturbed.inp")
with open(perturbed_deck, "w") as f:
    f.write(perturbed)
rc = run(["--tether-deck", perturbed_deck], "perturbed")
expect(rc == 1, f"perturbed deck: exit {rc}, expected 1")

# 3. ccx missing
rc = run(["--ccx", "/nonexistent/ccx"], "missing")
expect(rc == 2, f"missing ccx: exit {rc}, expected 2")

for f in failures:
    print("FAILED: " + f)
sys.exit(1 if failures else 0)
