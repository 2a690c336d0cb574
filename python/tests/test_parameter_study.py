"""Change material constants, loads and step data and run again without reading the deck again."""
import pytest

import tether
from conftest import bar_deck


def tip(inc):
    return inc.U[list(inc.node_labels).index(10), 0]


def test_change_young_and_loads_and_run_again():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    job = tether.Job(model)
    job.run()
    first = job.results[-1]
    steel = model.materials["STEEL"]
    assert steel.young == 1000.0 and steel.poisson == 0.25
    steel.young = 2000.0
    for load in model.steps[0].cloads:
        load.magnitude *= 3
    assert [load.node for load in model.steps[0].cloads] == [5, 10, 15]
    assert job.run()
    # Linear: three times the load on twice the stiffness.
    assert tip(job.results[-1]) == pytest.approx(1.5 * tip(first), rel=1e-12)
    # The first run's increments are unchanged.
    assert tip(first) == pytest.approx(10.0 * 4 / (1000 * 0.5), rel=1e-12)


def test_step_data():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    step = model.steps[0]
    assert (step.period, step.initial_increment) == (1.0, 0.5)
    step.initial_increment = 0.25
    step.max_increment = 0.25
    job = tether.Job(model)
    assert job.run()
    assert [inc.increment for inc in job.results] == [1, 2, 3, 4]
    step.nlgeom = True
    assert job.run() and model.steps[0].nlgeom


def test_prescribed_displacement_and_sweep():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    fixed = model.steps[0].boundary[0]
    assert (fixed.node, fixed.dof, fixed.value) == (1, 1, 0.0)
    tips = []
    for young in (500.0, 1000.0, 4000.0):
        model.materials["STEEL"].young = young
        job = tether.Job(model, keep="last")
        assert job.run()
        assert len(job.results) == 1
        tips.append(tip(job.results[-1]) * young)
    assert tips == pytest.approx([tips[0]] * 3, rel=1e-12)


def test_bad_values_are_refused():
    model = tether.read_deck_string(bar_deck(), name="bar.inp")
    with pytest.raises(ValueError):
        model.materials["STEEL"].young = -1
    with pytest.raises(ValueError):
        model.materials["STEEL"].poisson = 0.5
    with pytest.raises(ValueError):
        model.steps[0].period = 0
    with pytest.raises(AttributeError):
        model.materials["STEEL"].c10


def test_friction_coefficient_sweep(source):
    # A block pressed by p = 10 (N = 10) and pushed sideways slides at T = mu N.
    model = tether.read_deck(source / "tests/smoke/decks/contact_friction.inp")
    interaction = model.interactions["I"]
    assert interaction.law == "hard" and interaction.has_friction and interaction.mu == 0.3
    job = tether.Job(model, keep="last")
    for mu in (0.1, 0.3, 0.5):
        interaction.mu = mu
        assert job.run(check=True)
        (pair,) = job.results[-1].contact.values()
        assert (pair.status[pair.closed] == "slip").all()
        assert abs(pair.total_force[0]) == pytest.approx(mu * pair.total_force[1], rel=1e-6)
    with pytest.raises(ValueError):
        interaction.mu = -0.1
    with pytest.raises(ValueError, match="not LINEAR"):
        interaction.stiffness = 1e3
