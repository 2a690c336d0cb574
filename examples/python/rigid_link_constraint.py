#!/usr/bin/python3
"""The seed's rigid link written in Python, against *MPC LINK and the exact link force.

Runs examples/rigid_link/rigid_link.inp twice: as the deck is (*MPC LINK), and
with the link replaced by a constraint written in Python, f = |x_b - x_a| - L
with its gradient and Hessian, enforced by the same multiplier element. Prints
the link force of both beside the exact N = P / sin(theta) per increment and
the largest difference between the two runs.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/rigid_link_constraint.py [--check]

--check: exit 1 when the runs differ by more than 1e-10 (relative) or the
link force is off N by more than 1e-8 (relative).
"""
import argparse
import math
import pathlib
import sys

import numpy as np

import tether

DECK = pathlib.Path(__file__).resolve().parent.parent / "rigid_link" / "rigid_link.inp"
P = 3.0  # the downward load on B


def f(u, X):
    """|x_b - x_a| - L: u and X hold (x, y) of node a, then of node b."""
    x = X + u
    return np.hypot(*(x[2:] - x[:2])) - np.hypot(*(X[2:] - X[:2]))


def gradient(u, X):
    x = X + u
    n = (x[2:] - x[:2]) / np.hypot(*(x[2:] - x[:2]))
    return np.concatenate([-n, n])


def hessian(u, X):
    x = X + u
    d = x[2:] - x[:2]
    length = np.hypot(*d)
    n = d / length
    a = (np.eye(2) - np.outer(n, n)) / length
    return np.block([[a, -a], [-a, a]])


def run(python_link):
    model = tether.read_deck(DECK)
    if python_link:
        model.remove_constraint("LINK")
        model.add_constraint("LINK", nodes=[1, 2], f=f, gradient=gradient, hessian=hessian)
    job = tether.Job(model)
    job.run(check=True)
    return job.results


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    native, python = run(False), run(True)
    print(f"{'time':>6} {'theta [deg]':>12} {'N exact':>12} {'*MPC LINK':>12} {'Python':>12}")
    worst_difference = worst_error = 0.0
    for a, b in zip(native, python):
        x_b = b.X[1] + b.U[1]
        theta = math.atan2(-x_b[1], x_b[0])
        exact = P / math.sin(theta)
        n_native, n_python = a.multipliers["LINK"].value[0], b.multipliers["LINK"].value[0]
        worst_error = max(worst_error, abs(n_python / exact - 1))
        scale = max(np.abs(a.U).max(), np.abs(a.RF).max(), abs(n_native))
        worst_difference = max(worst_difference, np.abs(a.U - b.U).max() / scale, np.abs(a.RF - b.RF).max() / scale,
                               abs(n_native - n_python) / scale)
        print(f"{b.time:6.2f} {math.degrees(theta):12.4f} {exact:12.6f} {n_native:12.6f} {n_python:12.6f}")
    print(f"largest difference Python - *MPC LINK: {worst_difference:.2e} (relative); "
          f"largest error against N: {worst_error:.2e}")
    return 1 if args.check and (worst_difference > 1e-10 or worst_error > 1e-8) else 0


if __name__ == "__main__":
    sys.exit(main())
