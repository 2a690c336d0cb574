"""Constraints written in Python, enforced by the same multiplier element as the deck's."""
import time

import numpy as np
import pytest

import tether


def link_f(u, X):
    """The seed's rigid link: f = |x_b - x_a| - L with x = X + u."""
    x = X + u
    return np.hypot(*(x[2:] - x[:2])) - np.hypot(*(X[2:] - X[:2]))


def link_gradient(u, X):
    x = X + u
    d = x[2:] - x[:2]
    n = d / np.hypot(*d)
    return np.concatenate([-n, n])


def link_hessian(u, X):
    x = X + u
    d = x[2:] - x[:2]
    length = np.hypot(*d)
    n = d / length
    a = (np.eye(2) - np.outer(n, n)) / length
    return np.block([[a, -a], [-a, a]])


ENFORCEMENTS = {
    "lagrange": ("", {}),
    "penalty": (", ENFORCEMENT=PENALTY, PENALTY=1e4", {"penalty": 1e4}),
    "augmented": (", ENFORCEMENT=AUGMENTED, PENALTY=1e3, TOLERANCE=1e-12", {"penalty": 1e3, "tolerance": 1e-12}),
}


def rigid_link_deck(source, parameters=""):
    text = (source / "examples/rigid_link/rigid_link.inp").read_text()
    return text.replace("*MPC, NAME=LINK", "*MPC, NAME=LINK" + parameters)


@pytest.mark.parametrize("method", ENFORCEMENTS)
def test_python_rigid_link_reproduces_mpc_link(source, method):
    parameters, options = ENFORCEMENTS[method]
    native = tether.Job(tether.read_deck_string(rigid_link_deck(source, parameters), name="rigid_link.inp"))
    assert native.run(check=True)
    model = tether.read_deck_string(rigid_link_deck(source), name="rigid_link.inp")
    model.remove_constraint("LINK")
    model.add_constraint("LINK", nodes=[1, 2], f=link_f, gradient=link_gradient, hessian=link_hessian,
                         enforcement=method, **options)
    job = tether.Job(model)
    assert job.run(check=True)
    assert len(job.results) == len(native.results) == 20
    # To 1e-10 of the largest value (penalty multiplies the round-off of f by rho).
    for a, b in zip(job.results, native.results):
        assert np.abs(a.U - b.U).max() < 1e-10 * np.abs(b.U).max()
        assert np.abs(a.RF - b.RF).max() < 1e-10 * np.abs(b.RF).max()
        assert a.multipliers["LINK"].value == pytest.approx(b.multipliers["LINK"].value, rel=1e-10)
        assert a.multipliers["LINK"].constraint == pytest.approx(b.multipliers["LINK"].constraint, abs=1e-12)


def test_two_equations_reproduce_mpc_tie(source):
    # u_a = u_b in both directions (m = 2, linear, no Hessian): the deck's *MPC TIEs.
    text = (source / "tests/smoke/decks/mpc_tie.inp").read_text()
    native = tether.Job(tether.read_deck_string(text, name="tie.inp"))
    assert native.run(check=True)
    model = tether.read_deck_string(text, name="tie.inp")
    for name in model.constraints:
        nodes = list(native.results[-1].multipliers[name].node_labels)
        model.remove_constraint(name)
        model.add_constraint(name, nodes=nodes, f=lambda u, X: u[:2] - u[2:],
                             gradient=lambda u, X: np.hstack([np.eye(2), -np.eye(2)]))
    job = tether.Job(model)
    assert job.run(check=True)
    assert np.abs(job.results[-1].U - native.results[-1].U).max() < 1e-12
    for name in model.constraints:
        assert job.results[-1].multipliers[name].value == pytest.approx(
            native.results[-1].multipliers[name].value, abs=1e-10)


def test_bad_constraints_are_refused(source):
    model = tether.read_deck(source / "examples/rigid_link/rigid_link.inp")
    with pytest.raises(KeyError, match="no node 99"):
        model.add_constraint("C", nodes=[1, 99], f=link_f, gradient=link_gradient)
    with pytest.raises(ValueError, match="penalty"):
        model.add_constraint("C", nodes=[1, 2], f=link_f, gradient=link_gradient, enforcement="penalty")
    with pytest.raises(KeyError):
        model.remove_constraint("NOTHING")
    model.remove_constraint("LINK")
    model.add_constraint("C", nodes=[1, 2], f=link_f, gradient=lambda u, X: np.zeros(3))
    with pytest.raises(ValueError, match=r"constraint C: gradient returned shape \(3\), expected \(1, 4\)"):
        tether.Job(model).run()


def test_an_exception_in_the_constraint_propagates(source):
    model = tether.read_deck(source / "examples/rigid_link/rigid_link.inp")
    model.remove_constraint("LINK")

    def broken(u, X):
        if np.any(u != 0):
            raise ZeroDivisionError("inside f")
        return link_f(u, X)

    model.add_constraint("LINK", nodes=[1, 2], f=broken, gradient=link_gradient, hessian=link_hessian)
    with pytest.raises(ZeroDivisionError, match="inside f"):
        tether.Job(model).run()


def test_cost_of_one_evaluation(source):
    """Measures (prints) the time of one evaluation of a Python constraint,
    counted by the callables, beside the native *MPC LINK run. Not asserted."""
    calls = {"f": 0}

    def counted_f(u, X):
        calls["f"] += 1
        return link_f(u, X)

    model = tether.read_deck(source / "examples/rigid_link/rigid_link.inp")
    native_model = model.copy()
    model.remove_constraint("LINK")
    model.add_constraint("LINK", nodes=[1, 2], f=counted_f, gradient=link_gradient, hessian=link_hessian)

    def best(m, n=5):
        times = []
        for _ in range(n):
            t = time.perf_counter()
            tether.Job(m, keep="none").run(check=True)
            times.append(time.perf_counter() - t)
        return min(times)

    t_native = best(native_model)
    calls["f"] = 0
    t_python = best(model, 1)
    evaluations = calls["f"]
    t_python = best(model)
    per_evaluation = (t_python - t_native) / evaluations
    print(f"\nrigid link, 20 increments: native {t_native * 1e3:.2f} ms, Python {t_python * 1e3:.2f} ms, "
          f"{evaluations} evaluations, {per_evaluation * 1e6:.1f} us per evaluation (f, gradient, Hessian)")
    assert evaluations > 20


def test_time_dependent_constraint():
    # u_x of the bar's tip node 10 driven to 1e-3 t by a Python constraint
    # (time=True: the callables get the total time), instead of the load.
    from conftest import bar_deck
    model = tether.read_deck_string(bar_deck(force=0.0), name="bar.inp")
    model.add_constraint("DRIVE", nodes=[10], f=lambda u, X, t: u[0] - 1e-3 * t,
                         gradient=lambda u, X, t: np.array([1.0, 0.0]), time=True)
    job = tether.Job(model)
    assert job.run(check=True)
    tip = list(job.results[0].node_labels).index(10)
    assert [inc.U[tip, 0] for inc in job.results] == pytest.approx([0.5e-3, 1e-3], abs=1e-15)
    # The constraint's force is the reaction the tip needs: balanced by the support.
    last = job.results[-1]
    assert last.multipliers["DRIVE"].force[0, 0] == pytest.approx(-last.RF[:, 0].sum(), rel=1e-9)
