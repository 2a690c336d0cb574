#!/usr/bin/env python3
"""Neck radius ratio against the pull of the necking bar (decks from make_deck.py).

    plot_necking.py RUN.dat [RUN2.dat ...] [--label L ...] [--png necking.png]

Reads the `displacements ... for set NECK` blocks of each .dat (tether's or
CalculiX's; the step time t gives the pull 7 t mm) and prints, per run, the
ratio of the current to the initial radius at the neck, (r0 + u_r) / r0 with
r0 = 0.982 x 6.413 mm, at every increment; --png plots them all.
"""
import argparse
import re

R0 = 6.413 * 0.982
BLOCK = re.compile(r"displacements \(vx,vy,vz\) for set NECK and time\s+(\S+)\s*\n\s*\n\s*\d+\s+(\S+)")


def history(path):
    with open(path) as f:
        text = f.read()
    return [(0.0, 1.0)] + [(7 * float(t), (R0 + float(u)) / R0) for t, u in BLOCK.findall(text)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dat", nargs="+")
    ap.add_argument("--label", action="append", default=[])
    ap.add_argument("--png")
    opts = ap.parse_args()
    labels = opts.label + opts.dat[len(opts.label):]
    runs = [(label, history(path)) for label, path in zip(labels, opts.dat)]
    for label, rows in runs:
        print(f"{label}: {len(rows) - 1} increments; pull [mm], neck radius ratio:")
        print("  " + "  ".join(f"{d:.3f} {q:.4f}" for d, q in rows[1:] if abs(2 * d - round(2 * d)) < 0.07 or d == rows[-1][0]))
    if opts.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for label, rows in runs:
            ax.plot([d for d, _ in rows], [q for _, q in rows], label=label)
        ax.set_xlabel("pull of the half bar [mm] (elongation / 2)")
        ax.set_ylabel("neck radius / initial radius")
        ax.grid(True, alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(opts.png, dpi=120)


if __name__ == "__main__":
    main()
