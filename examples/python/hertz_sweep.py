#!/usr/bin/python3
"""Hertz load sweep from Python: the peak contact pressure p0 against the line load P.

Reads examples/hertz/hertz.inp once (plane-strain cylinder R = 10 mm on a block,
both E = 200 000 MPa, nu = 0.3, symmetric half model loaded by a pressure
P / (2R) on the cylinder's flat top), then for each P changes that pressure and
runs again, without reading the deck again. Prints p0 (the largest nodal
contact pressure) beside the closed form p0 = 2P / (pi a), a = sqrt(4PR / (pi E*)),
E* = E / (2 (1 - nu^2)), and plots both.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/hertz_sweep.py [--png hertz_sweep.png] [--check]

--check: exit 1 when a p0 is off the closed form by more than 1 %.
"""
import argparse
import math
import pathlib
import sys

import tether

HERE = pathlib.Path(__file__).resolve().parent
R, E, NU = 10.0, 200000.0, 0.3


def exact_p0(load):
    """Peak pressure of plane-strain Hertz contact under the line load `load` [N/mm]."""
    e_star = E / (2.0 * (1.0 - NU * NU))
    a = math.sqrt(4.0 * load * R / (math.pi * e_star))
    return 2.0 * load / (math.pi * a)


def sweep(loads):
    """[(P, p0 computed)] for each line load P."""
    model = tether.read_deck(HERE.parent / "hertz" / "hertz.inp")
    job = tether.Job(model, keep="last")
    rows = []
    for load in loads:
        for pressure in model.steps[0].pressures:
            pressure.magnitude = load / (2.0 * R)
        job.run(check=True)
        (pair,) = job.results[-1].contact.values()
        rows.append((load, float(pair.pressure.max())))
    return rows


def plot(rows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    loads = [p for p, _ in rows]
    fine = [loads[0] * 0.9 + k * (loads[-1] * 1.05 - loads[0] * 0.9) / 100 for k in range(101)]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    ax.plot(fine, [exact_p0(p) for p in fine], "-", color="0.4", label=r"Hertz: $p_0 = \sqrt{P E^*/(\pi R)}$")
    ax.plot(loads, [p0 for _, p0 in rows], "o", color="C0", label="tether (peak nodal pressure)")
    ax.set_xlabel("line load P [N/mm]")
    ax.set_ylabel("peak contact pressure $p_0$ [MPa]")
    ax.set_title("Hertz load sweep (2k dofs), one deck read")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--png", help="write the plot here")
    parser.add_argument("--check", action="store_true", help="exit 1 when an error exceeds 1 %%")
    args = parser.parse_args()
    rows = sweep([500.0, 1000.0, 1500.0, 2000.0, 2500.0])
    worst = 0.0
    print(f"{'P [N/mm]':>10} {'p0 tether':>12} {'p0 Hertz':>12} {'error':>9}")
    for load, p0 in rows:
        error = p0 / exact_p0(load) - 1.0
        worst = max(worst, abs(error))
        print(f"{load:10.1f} {p0:12.2f} {exact_p0(load):12.2f} {100 * error:8.3f}%")
    print(f"largest error {100 * worst:.3f} %")
    if args.png:
        plot(rows, args.png)
    return 1 if args.check and worst > 0.01 else 0


if __name__ == "__main__":
    sys.exit(main())
