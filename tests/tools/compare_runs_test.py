#!/usr/bin/python3
"""Test of tools/compare_runs.py: usage compare_runs_test.py SOURCE_DIR TETHER WORKDIR.

On the Lame example deck:
1. the same program as `before` and `after`: exit 0, "2 of 2 cases identical"
   (the deck as it is and with --solver cholmod);
2. an `after` that changes one digit of the .dat: exit 1, the .dat named;
3. an `after` that changes only the timing line of the .msg: exit 0 (timing is
   ignored; the wrapper exits 9 if it found no timing line to change);
4. an `after` that exits with another code: exit 1, the exit codes named.
"""
import os
import shutil
import stat
import subprocess
import sys

source, tether, work = sys.argv[1:4]
tether = os.path.abspath(tether)
tool = os.path.join(source, "tools", "compare_runs.py")
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
failures = []


def wrapper(name, after_run):
    """A program that runs tether, then the shell commands `after_run` in its output directory."""
    os.makedirs(os.path.join(work, "bin"), exist_ok=True)
    path = os.path.join(work, "bin", name)
    with open(path, "w") as f:
        f.write(f"""#!/bin/sh
"{tether}" "$@"; rc=$?
out=""; prev=""
for a in "$@"; do [ "$prev" = "-o" ] && out="$a"; prev="$a"; done
cd "$out" || exit $rc
{after_run}
exit $rc
""")
    os.chmod(path, os.stat(path).st_mode | stat.S_IXUSR)
    return path


def run(after, name):
    cmd = ["/usr/bin/python3", tool, "--before", tether, "--after", after, "--work", os.path.join(work, name),
           "--only", "examples_lame_lame.inp"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    print(f"$ {' '.join(cmd)}\n{proc.stdout}{proc.stderr}")
    return proc.returncode, proc.stdout


def expect(cond, what):
    if not cond:
        failures.append(what)


rc, out = run(tether, "same")
expect(rc == 0 and "2 of 2 cases identical" in out, "same program: exit 0, 2 of 2 identical")
rc, out = run(wrapper("changed_dat", "sed -i '4s/9/8/' lame.dat"), "changed_dat")
expect(rc == 1 and "DIFFERS: lame.dat" in out, "changed .dat: exit 1 naming lame.dat")
rc, out = run(wrapper("changed_timing", "sed -i 's/^  time [0-9.]* s:/  time 999.99 s:/' lame.msg\ngrep -q 'time 999.99 s:' lame.msg || exit 9"), "timing")
expect(rc == 0, "changed timing line only: exit 0")
rc, out = run(wrapper("exit_code", "exit 3"), "exit_code")
expect(rc == 1 and "exit code 0 vs 3" in out, "changed exit code: exit 1 naming the codes")

for f in failures:
    print("FAILED:", f)
sys.exit(1 if failures else 0)
