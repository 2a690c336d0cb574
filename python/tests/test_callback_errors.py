"""A Python exception in a callback (progress, a Python constraint) stops the run: Python
gets the exception itself, and the files end with a verdict naming what failed and the
last increment written."""
import numpy as np
import pytest

import tether
from conftest import bar_deck
from tethertools import dat, sta  # tools/ on PYTHONPATH


def test_progress_callback_exception_ends_the_sta_with_a_verdict(tmp_path):
    job = tether.Job(tether.read_deck_string(bar_deck(), name="bar.inp"), output_dir=tmp_path)

    def progress(report):
        if report.increment == 2:
            raise ValueError("stop at the second increment")

    with pytest.raises(ValueError, match="stop at the second increment") as raised:
        job.run(progress=progress)
    assert any("progress callback" in note for note in getattr(raised.value, "__notes__", []))
    assert [(r.step, r.increment) for r in job.results] == [(1, 1)]  # kept until the exception

    completed, message = sta.verdict(tmp_path / "bar.sta")
    assert not completed
    assert "ValueError: stop at the second increment" in message
    assert "progress callback" in message
    assert "last increment written: step 1 increment 1, time 0.5" in message
    msg = (tmp_path / "bar.msg").read_text()
    assert message in msg  # the same verdict closes the message log
    assert sta.converged_increments_in_msg(tmp_path / "bar.msg") == [(1, 1, 0.5), (1, 2, 1.0)]
    # The .dat holds what was written: the first increment only.
    times = {b["time"] for b in dat.read(tmp_path / "bar.dat") if b["title"].startswith("displacements")}
    assert times == {0.5}


def test_python_constraint_exception_ends_the_sta_with_a_verdict(tmp_path, source):
    model = tether.read_deck(source / "examples/rigid_link/rigid_link.inp")
    model.remove_constraint("LINK")
    def f(u, X, t):
        if t > 0.25:
            raise RuntimeError(f"f cannot go past t = {t:g}")
        x = X + u
        return np.hypot(*(x[2:] - x[:2])) - np.hypot(*(X[2:] - X[:2]))

    def gradient(u, X, t):
        x = X + u
        d = x[2:] - x[:2]
        return np.concatenate([-d, d]) / np.hypot(*d)

    model.add_constraint("LINK", nodes=[1, 2], f=f, gradient=gradient, time=True)
    job = tether.Job(model, output_dir=tmp_path, name="link")
    with pytest.raises(RuntimeError, match="f cannot go past") as raised:
        job.run()
    assert any("constraint LINK" in note for note in getattr(raised.value, "__notes__", []))
    written = [(r.step, r.increment, r.time) for r in job.results]
    assert written and all(t <= 0.25 for _, _, t in written)

    completed, message = sta.verdict(tmp_path / "link.sta")
    assert not completed
    assert "RuntimeError: f cannot go past" in message and "constraint LINK" in message
    step, increment, time = written[-1]
    assert f"last increment written: step {step} increment {increment}, time {time:g}" in message
    assert message in (tmp_path / "link.msg").read_text()


def test_without_output_dir_the_exception_still_reaches_python():
    job = tether.Job(tether.read_deck_string(bar_deck(), name="bar.inp"))
    with pytest.raises(KeyError):
        job.run(progress=lambda report: {}["missing"])
    assert job.results == []
