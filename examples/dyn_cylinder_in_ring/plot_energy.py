#!/usr/bin/env python3
"""Energy history of the cylinder in a ring, against the closed form.

    /usr/bin/python3 plot_energy.py cylinder_in_ring/cylinder_in_ring.dat [--png cylinder_in_ring.png]

Reads the centre node's U and V (*NODE PRINT, NSET=CENTRE) from the .dat and
the energies from the JOB_energy.csv beside it. Potential energy
m g (y_c + 0.7) = m g 0.7 - ALLWK (gravity is the only load doing work; the
ring is held), m = rho pi R^2 depth = 12.566 kg. Closed form: the total
ALLKE + ALLSE + potential stays m g 0.7 = 86.2632 J, the speed at height y_c
is sqrt(-2 g y_c), 3.705 m/s at the bottom.
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from tethertools import dat  # noqa: E402

G, MASS, DROP, X0 = 9.80665, 1000 * math.pi * 0.2 ** 2 * 0.1, 0.7, -0.7
ENERGY, SPEED = MASS * G * DROP, math.sqrt(2 * G * DROP)


def centre_motion(dat_path):
    """{time: (x, y, vx, vy)} of the centre node."""
    out = {}
    for b in dat.read(dat_path):
        if b["set"] != "CENTRE" or not b["rows"]:
            continue
        row = b["rows"][0]
        x, y, vx, vy = out.get(b["time"], (0.0, 0.0, 0.0, 0.0))
        if b["title"].startswith("displacements"):
            x, y = X0 + row[1], row[2]
        elif b["title"].startswith("velocities"):
            vx, vy = row[1], row[2]
        out[b["time"]] = (x, y, vx, vy)
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dat")
    parser.add_argument("--png")
    args = parser.parse_args()
    motion = centre_motion(args.dat)
    energy_path = os.path.splitext(args.dat)[0] + "_energy.csv"
    with open(energy_path) as f:
        energies = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    times = sorted(motion)
    bottom = None
    for t0, t1 in zip(times, times[1:]):
        (x0, _, vx0, vy0), (x1, _, vx1, vy1) = motion[t0], motion[t1]
        if x0 < 0 <= x1:
            w = -x0 / (x1 - x0)
            bottom = (t0 + w * (t1 - t0), (1 - w) * math.hypot(vx0, vy0) + w * math.hypot(vx1, vy1))
            break
    by_time = {r["time"]: r for r in energies}
    rows = [by_time[t] for t in times if t in by_time]
    if bottom:
        t_b, v_b = bottom
        k = max(i for i, r in enumerate(energies) if r["time"] <= t_b)
        a, b = energies[k], energies[min(k + 1, len(energies) - 1)]
        w = 0 if b["time"] == a["time"] else (t_b - a["time"]) / (b["time"] - a["time"])
        e_b = (1 - w) * (a["ALLKE"] + a["ALLSE"]) + w * (b["ALLKE"] + b["ALLSE"])
        v_k = math.sqrt(2 * ((1 - w) * a["ALLKE"] + w * b["ALLKE"]) / MASS)
        bottom = (t_b, v_b, v_k)
        print(f"bottom at t = {t_b:.4f} s: speed sqrt(2 ALLKE / m) {v_k:.4f} m/s against {SPEED:.4f} "
              f"({100 * (v_k / SPEED - 1):+.3f} %; the centre node {v_b:.4f}, {100 * (v_b / SPEED - 1):+.3f} %), "
              f"ALLKE + ALLSE {e_b:.4f} J against {ENERGY:.4f} ({100 * (e_b / ENERGY - 1):+.3f} %)")
    totals = [r["ALLKE"] + r["ALLSE"] + ENERGY - r["ALLWK"] for r in energies]
    print(f"total energy (ALLKE + ALLSE + m g (y_c + 0.7)): {min(totals):.4f} .. {max(totals):.4f} J against {ENERGY:.4f}; "
          f"largest |numerical| {max(abs(r['NUMERICAL']) for r in energies):.4g} J")
    if not args.png:
        return
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax_e, ax_v) = plt.subplots(1, 2, figsize=(11, 4.2))
    t = [r["time"] for r in energies]
    ax_e.plot(t, [r["ALLKE"] for r in energies], label="kinetic ALLKE")
    ax_e.plot(t, [ENERGY - r["ALLWK"] for r in energies], label="potential $m g (y_c + 0.7)$")
    ax_e.plot(t, [100 * r["ALLSE"] for r in energies], label="strain ALLSE × 100")
    ax_e.plot(t, totals, "k", lw=1.5, label="total")
    ax_e.plot(t, [100 * r["NUMERICAL"] for r in energies], "k:", label="numerical × 100")
    ax_e.axhline(ENERGY, color="0.6", lw=3, zorder=0, label=f"closed form {ENERGY:.4f} J")
    ax_e.set_xlabel("time [s]"), ax_e.set_ylabel("energy [J]"), ax_e.set_title("energies")
    ax_e.legend(fontsize=7), ax_e.grid(alpha=0.3)
    ax_v.plot(t, [math.sqrt(2 * r["ALLKE"] / MASS) for r in energies], label="tether $\\sqrt{2\\,ALLKE/m}$")
    ax_v.plot(times, [math.hypot(motion[s][2], motion[s][3]) for s in times], lw=0.7, label="tether, centre node")
    ax_v.plot(times, [math.sqrt(max(0.0, -2 * G * motion[s][1])) for s in times], color="0.6", lw=3, zorder=0,
              label="closed form $\\sqrt{-2 g y_c}$")
    if bottom:
        ax_v.plot([bottom[0]], [bottom[2]], "o", color="C3", label=f"bottom: {bottom[2]:.4f} m/s (closed form {SPEED:.3f})")
    ax_v.set_xlabel("time [s]"), ax_v.set_ylabel("speed [m/s]"), ax_v.set_title("speed of the cylinder")
    ax_v.legend(fontsize=7), ax_v.grid(alpha=0.3)
    fig.suptitle("cylinder (Ø 0.4 m) sliding without friction in a fixed ring (Ø 1.8 m) under gravity, explicit",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(args.png, dpi=110)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    main()
