"""Job(output_dir=...) writes what `tether run` writes; without it nothing is written."""
import ctypes
import ctypes.util
import os
import subprocess

import numpy as np
import pytest

import tether
from conftest import bar_deck
from tethertools import dat  # tools/ on PYTHONPATH


def openblas_kernels():
    """The OpenBLAS kernels this process runs ("Prescott", "SkylakeX", ...), or None."""
    name = ctypes.util.find_library("openblas")
    try:
        corename = ctypes.CDLL(name or "libopenblas.so.0").openblas_get_corename
    except (OSError, AttributeError):
        return None
    corename.restype = ctypes.c_char_p
    return corename().decode()


def test_nothing_written_without_output_dir(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    job = tether.Job(tether.read_deck_string(bar_deck(), name="bar.inp"))
    assert job.run()
    assert job.output_dir is None and job.written_files == []
    assert list(tmp_path.iterdir()) == []


def test_output_dir_gets_the_files_of_tether_run(tmp_path):
    deck = tmp_path / "bar.inp"
    deck.write_text(bar_deck())
    job = tether.Job(tether.read_deck(deck), output_dir=tmp_path / "py")
    assert job.run()
    assert job.name == "bar"
    assert sorted(p.name for p in job.written_files) == ["bar.dat", "bar.msg", "bar.pvd", "bar.sta"]
    cli = os.environ.get("TETHER_CLI")
    if not cli:
        pytest.skip("TETHER_CLI not set")
    # The same BLAS kernels as this process: `tether run` otherwise replaces
    # OpenBLAS's generic kernels by better ones (docs/theory/condensation.md),
    # and other kernels change the last bits.
    env = dict(os.environ)
    if "OPENBLAS_CORETYPE" not in env and openblas_kernels():
        env["OPENBLAS_CORETYPE"] = openblas_kernels()
    subprocess.run([cli, "run", str(deck), "-o", str(tmp_path / "cli"), "-q"], check=True, env=env)
    names = sorted(p.name for p in (tmp_path / "py").iterdir())
    assert names == sorted(p.name for p in (tmp_path / "cli").iterdir())
    py_blocks = dat.parse((tmp_path / "py/bar.dat").read_text())
    cli_blocks = dat.parse((tmp_path / "cli/bar.dat").read_text())
    assert [(b["title"], b["set"], b["time"]) for b in py_blocks] == [(b["title"], b["set"], b["time"]) for b in cli_blocks]
    for a, b in zip(py_blocks, cli_blocks):
        assert np.array_equal(np.array(a["rows"]), np.array(b["rows"]))
    # ... and the .dat holds the increment the Job kept.
    u = [b for b in py_blocks if b["title"].startswith("displacements")][-1]
    inc = job.results[-1]
    for row in u["rows"]:
        k = np.searchsorted(inc.node_labels, int(row[0]))
        assert row[1:3] == pytest.approx(inc.U[k], rel=1e-6)
