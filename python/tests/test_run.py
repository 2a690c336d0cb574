"""The minimum contract: read a deck, run it, read the results as NumPy arrays."""
import math

import numpy as np
import pytest

import tether
from conftest import bar_deck


def test_rigid_link_multiplier_is_the_link_force(source):
    # examples/rigid_link: B driven along x on the circle |x_B - x_A| = 2 under
    # P = 3 downwards; equilibrium gives the link force N = P / sin(theta).
    model = tether.read_deck(source / "examples/rigid_link/rigid_link.inp")
    job = tether.Job(model, output_dir=None)
    summary = job.run(progress=None)
    assert summary.completed, summary.message
    assert summary.message == "analysis complete"
    assert len(job.results) == summary.increments == 20
    inc = job.results[-1]
    assert (inc.step, inc.increment) == (1, 20)
    assert inc.time == pytest.approx(1.0)
    assert list(inc.node_labels) == [1, 2]
    assert inc.U.shape == (2, 2) and inc.RF.shape == (2, 2)
    x_b = inc.X[1] + inc.U[1]
    theta = math.atan2(-x_b[1], x_b[0])
    assert np.hypot(*x_b) == pytest.approx(2.0, abs=1e-10)
    link = inc.multipliers["LINK"]
    assert link.value[0] == pytest.approx(3.0 / math.sin(theta), rel=1e-8)
    assert abs(link.constraint[0]) < 1e-10
    # The reaction at the pin A balances the link's pull on it.
    assert inc.RF[0] == pytest.approx(-link.force[0], abs=1e-9)
    # Every increment is its own snapshot.
    times = [i.time for i in job.results]
    assert times == sorted(times) and times[0] == pytest.approx(0.05)


def test_stresses_at_integration_points_and_arrays_are_read_only():
    job = tether.Job(tether.read_deck_string(bar_deck(), name="bar.inp"))
    assert job.run()
    inc = job.results[-1]
    assert inc.S.shape == (32, 4) and inc.E.shape == (32, 4)
    assert list(inc.element_labels[:5]) == [1, 1, 1, 1, 2]
    assert list(inc.integration_points[:5]) == [1, 2, 3, 4, 1]
    assert np.allclose(inc.S[:, 0], 10.0 / 0.5, rtol=1e-10)
    assert np.allclose(inc.S[:, 1:], 0, atol=1e-9)
    tip = np.searchsorted(inc.node_labels, 10)
    assert inc.U[tip, 0] == pytest.approx(10.0 * 4 / (1000 * 0.5), rel=1e-12)
    with pytest.raises(ValueError):
        inc.U[0, 0] = 1.0
    # The arrays keep their increment alive.
    u = job.results[0].U
    del job, inc
    assert u[tip, 0] == pytest.approx(0.5 * 10.0 * 4 / (1000 * 0.5), rel=1e-12)


def test_contact_state_per_slave_node(source):
    # Block pressed by p = 10 over width 1 onto another: the contact force on
    # the slave body balances the load.
    with pytest.warns(tether.DeckWarning, match="CELS"):
        model = tether.read_deck(source / "tests/smoke/decks/contact_hard.inp")
    job = tether.Job(model)
    assert job.run().completed
    (name, pair), = job.results[-1].contact.items()
    assert name.startswith("CONTACT PAIR ")
    # (frictionless: x to within the residual tolerance of the deck's *CONTROLS)
    assert pair.total_force == pytest.approx([0.0, 10.0], abs=1e-4)
    assert set(pair.status) <= {"open", "stick", "slip"}
    assert pair.closed.all()
    assert pair.pressure.shape == pair.gap.shape == pair.slip.shape == pair.node_labels.shape
    assert pair.force.sum(axis=0) == pytest.approx(pair.total_force, abs=1e-12)
    assert np.all(np.abs(pair.gap) < 1e-10)


def test_progress_callback_sees_every_attempt():
    seen = []
    job = tether.Job(tether.read_deck_string(bar_deck(), name="bar.inp"))
    summary = job.run(progress=seen.append)
    assert [(r.step, r.increment, r.attempt, r.converged) for r in seen] == [(1, 1, 1, True), (1, 2, 1, True)]
    assert seen[-1].time == pytest.approx(1.0)
    assert summary.increments == 2


def test_an_exception_in_the_callback_stops_the_run():
    def stop(report):
        raise KeyboardInterrupt("stop here")

    job = tether.Job(tether.read_deck_string(bar_deck(), name="bar.inp"))
    with pytest.raises(KeyboardInterrupt, match="stop here"):
        job.run(progress=stop)


def test_to_meshio():
    meshio = pytest.importorskip("meshio")
    job = tether.Job(tether.read_deck_string(bar_deck(), name="bar.inp"))
    job.run()
    mesh = job.results[-1].to_meshio()
    assert isinstance(mesh, meshio.Mesh)
    assert mesh.points.shape == (15, 3)
    assert mesh.cells[0].type == "quad" and mesh.cells[0].data.shape == (8, 4)
    assert np.array_equal(mesh.point_data["U"], job.results[-1].U)
    assert mesh.cell_data["S_mean"][0][:, 0] == pytest.approx(np.full(8, 20.0), rel=1e-10)


def test_ctrl_c_stops_a_long_run(source, tmp_path):
    # SIGINT (what Ctrl-C sends) 0.5 s into the ironing example (about 25 s, 44
    # increments): the run stops with KeyboardInterrupt within an iteration, so
    # the status file holds only the first few increments, and its verdict.
    import os
    import signal
    import threading

    model = tether.read_deck(source / "examples/ironing/ironing.inp")
    job = tether.Job(model, output_dir=tmp_path, name="ironing")
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            job.run()
    finally:
        timer.cancel()
    status = (tmp_path / "ironing.sta").read_text()
    attempts = [line for line in status.splitlines() if line.split()[:1] in (["1"], ["2"])]
    assert len(attempts) < 22, status  # the whole run: 44 increments
    verdict = " THE ANALYSIS HAS NOT BEEN COMPLETED: stopped by an exception: KeyboardInterrupt (a signal arrived " \
              "during the run); "
    if job.results:
        verdict += f"last increment written: step {job.results[-1].step} increment {job.results[-1].increment}"
    else:
        verdict += "no increment was written by this run"
    assert verdict in status, status
    # The increments that converged before are kept.
    assert len(job.results) == len(attempts)
    assert [(inc.step, inc.increment) for inc in job.results] == [tuple(map(int, a.split()[:2])) for a in attempts]


def test_to_meshio_mixed_element_shapes():
    meshio = pytest.importorskip("meshio")
    # Triangle, quad, two triangles (elements in that order): one cell block per run of a shape.
    deck = """*NODE
1, 0., 0.
2, 1., 0.
3, 2., 0.
4, 3., 0.
5, 0., 1.
6, 1., 1.
7, 2., 1.
8, 3., 1.
*ELEMENT, TYPE=CPS3, ELSET=E
1, 1, 2, 6
*ELEMENT, TYPE=CPS4, ELSET=E
2, 2, 3, 7, 6
*ELEMENT, TYPE=CPS3, ELSET=E
3, 3, 4, 7
4, 4, 8, 7
*MATERIAL, NAME=M
*ELASTIC
1000., 0.
*SOLID SECTION, ELSET=E, MATERIAL=M
1.
*BOUNDARY
1, 1, 2
2, 2
*STEP
*STATIC
*CLOAD
4, 1, 1.
8, 1, 1.
*END STEP
"""
    model = tether.read_deck_string(deck, name="mixed.inp")
    job = tether.Job(model)
    assert job.run(check=True)
    mesh = job.results[-1].to_meshio()
    assert [(c.type, len(c.data)) for c in mesh.cells] == [("triangle", 1), ("quad", 1), ("triangle", 2)]
    assert mesh.cells[1].data.tolist() == [[1, 2, 6, 5]]  # node indices, not labels
    assert [len(s) for s in mesh.cell_data["S_mean"]] == [1, 1, 2]
    inc = job.results[-1]
    quad = inc.S[inc.element_labels == 2]
    assert mesh.cell_data["S_mean"][1][0] == pytest.approx(quad.mean(axis=0), abs=1e-12)
