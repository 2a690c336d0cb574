#!/usr/bin/env python3
"""Plots the bar impact against its closed form and prints the errors.

    /usr/bin/python3 plot_bar_impact.py bar_impact/bar_impact.dat [--deck bar_impact.inp] [--png bar_impact.png]
        [--implicit bar_impact_implicit/bar_impact_implicit.dat]

Reads the wall's reaction (*NODE PRINT RF of WALLN) from the .dat and the
energies from the JOB_energy.csv beside it. Closed form: make_deck.py's docstring.
"""
import argparse
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from tethertools import dat  # noqa: E402

E, NU, RHO = 2e11, 0.3, 7800.0
CP = math.sqrt(E * (1 - NU) / (RHO * (1 + NU) * (1 - 2 * NU)))


def deck_parameters(deck):
    """(L, h, v0) from the heading make_deck.py wrote into `deck` (defaults without one)."""
    length, n, v0 = 1.0, 100, 1.0
    if deck:
        text = open(deck).read()
        m = re.search(r"--elements (\S+) --length (\S+) --v0 (\S+)", text)
        if m:
            n, length, v0 = int(m[1]), float(m[2]), float(m[3])
    return length, length / n, v0


def history(dat_path):
    """Times, wall forces [N per unit thickness] and energy rows of a run."""
    times, forces = [], []
    for b in dat.read(dat_path):
        if b["set"] == "WALLN" and b["title"].startswith("forces"):
            times.append(b["time"])
            forces.append(sum(r[1] for r in b["rows"]))
    energy_path = os.path.join(os.path.dirname(dat_path), os.path.splitext(os.path.basename(dat_path))[0] + "_energy.csv")
    with open(energy_path) as f:
        energies = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    return times, forces, energies


def closed_form(t, length, v0, area):
    """Contact force, kinetic and strain energy (per unit thickness) at time t."""
    m = RHO * length * area
    e0 = 0.5 * m * v0 * v0
    s = CP * t / length  # wave fronts in bar lengths
    force = RHO * CP * v0 * area if s < 2 else 0.0
    if s < 1:
        return force, e0 * (1 - s), e0 * s
    if s < 2:
        return force, e0 * (s - 1), e0 * (2 - s)
    return force, e0, 0.0


def summary(name, times, forces, energies, length, h, v0):
    expected = RHO * CP * v0 * h
    duration = 2 * length / CP
    inside = [f for t, f in zip(times, forces) if 0.05 * duration < t < 0.95 * duration]
    mean = sum(inside) / len(inside)
    released = None
    for (t0, f0), (t1, f1) in zip(zip(times, forces), zip(times[1:], forces[1:])):
        if f0 > 0.5 * expected >= f1:
            released = t0 + (t1 - t0) * (f0 - 0.5 * expected) / (f0 - f1)
            break
    e = energies[-1]
    m = RHO * length * h
    rebound = math.sqrt(2 * e["ALLKE"] / m)
    print(f"{name}: contact force {mean:.6g} N against rho c_p v0 A = {expected:.6g} ({100 * (mean / expected - 1):+.3f} %); "
          f"release at {released:.6g} s against 2L/c_p = {duration:.6g} s "
          f"({100 * (released / duration - 1) if released else float('nan'):+.3f} %); rebound speed from ALLKE "
          f"{rebound:.5g} m/s ({100 * (rebound / v0 - 1):+.3f} %); numerical energy {e['NUMERICAL']:.4g} J "
          f"of {0.5 * m * v0 * v0:.4g} J")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dat", help="the explicit run's .dat")
    parser.add_argument("--implicit", help="the implicit run's .dat (optional)")
    parser.add_argument("--deck", help="the deck (its heading gives L, h and v0; default 1 m, 0.01 m, 1 m/s)")
    parser.add_argument("--png", help="write the figure here")
    args = parser.parse_args()
    length, h, v0 = deck_parameters(args.deck)
    runs = [("explicit", args.dat)] + ([("implicit", args.implicit)] if args.implicit else [])
    data = {name: history(path) for name, path in runs}
    for name, (times, forces, energies) in data.items():
        summary(name, times, forces, energies, length, h, v0)
    if not args.png:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax_f, ax_e) = plt.subplots(1, 2, figsize=(11, 4.2))
    t_end = max(max(d[0]) for d in data.values())
    grid = [t_end * k / 1000 for k in range(1001)]
    exact = [closed_form(t, length, v0, h) for t in grid]
    ms = 1e3
    ax_f.plot([t * ms for t in grid], [e[0] / 1e3 for e in exact], color="0.6", lw=3, label="closed form $\\rho c_p v_0 A$")
    styles = {"explicit": "C0", "implicit": "C3"}
    for name, (times, forces, energies) in data.items():
        ax_f.plot([t * ms for t in times], [f / 1e3 for f in forces], styles[name], lw=1.2, label=f"tether {name}")
        et = [r["time"] * ms for r in energies]
        ax_e.plot(et, [r["ALLKE"] for r in energies], styles[name], lw=1.2, label=f"ALLKE {name}")
        ax_e.plot(et, [r["ALLSE"] for r in energies], styles[name], ls="--", lw=1.2, label=f"ALLSE {name}")
        ax_e.plot(et, [r["NUMERICAL"] for r in energies], styles[name], ls=":", lw=1.2, label=f"numerical {name}")
    ax_e.plot([t * ms for t in grid], [e[1] for e in exact], color="0.6", lw=3, zorder=0, label="closed form")
    ax_e.plot([t * ms for t in grid], [e[2] for e in exact], color="0.6", lw=3, ls="--", zorder=0)
    ax_f.set_xlabel("time [ms]"), ax_f.set_ylabel("wall force [kN per m thickness]")
    ax_e.set_xlabel("time [ms]"), ax_e.set_ylabel("energy [J per m thickness]")
    ax_f.set_title("contact force"), ax_e.set_title("energies")
    ax_f.legend(fontsize=8), ax_e.legend(fontsize=7, ncol=2)
    ax_f.grid(alpha=0.3), ax_e.grid(alpha=0.3)
    fig.suptitle(f"steel bar (L = {length:g} m, 1D strain) on a rigid wall at {v0:g} m/s", fontsize=10)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
