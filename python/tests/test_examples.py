"""The Python examples (examples/python) run and stay within their tolerances (--check):
the Hertz load sweep against the closed form (and its plot), the rigid link written in Python
against *MPC LINK."""
import os
import subprocess
import sys

import pytest

from conftest import SOURCE


@pytest.mark.parametrize("script, arguments", [
    ("hertz_sweep.py", ["--check", "--png", "{tmp}/hertz_sweep.png"]),
    ("rigid_link_constraint.py", ["--check"]),
])
def test_example(tmp_path, script, arguments):
    # No skip: matplotlib (for the sweep's plot) is one of scripts/install-deps.sh's packages.
    command = [sys.executable, str(SOURCE / "examples/python" / script)] + [a.format(tmp=tmp_path) for a in arguments]
    run = subprocess.run(command, capture_output=True, text=True, env=dict(os.environ), timeout=120)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "largest" in run.stdout
    if script == "hertz_sweep.py":
        assert (tmp_path / "hertz_sweep.png").stat().st_size > 10000
