#!/usr/bin/python3
"""Plots the nodal contact pressure of both patch-test runs against the exact
uniform pressure (reads the .dat 'contact state' block and the decks' nodes)."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

import tethertools.dat  # noqa: E402  (PYTHONPATH=../../tools)
import tethertools.deck  # noqa: E402

P = 10.0


def main():
    fig, ax = plt.subplots(figsize=(7, 4))
    for name, marker in (("fine_on_coarse", "o"), ("coarse_on_fine", "s")):
        x = {n: xy[0] for n, xy in tethertools.deck.Deck(f"{name}.inp").xy.items()}
        blocks = [b for b in tethertools.dat.read(os.path.join(name, name + ".dat")) if b["title"].startswith("contact state")]
        rows = sorted(blocks[-1]["rows"], key=lambda r: x[int(r[0])])
        xs, ps = [x[int(r[0])] for r in rows], [r[3] for r in rows]
        error = max(abs(p / P - 1) for p in ps)
        print(f"{name}: max pressure error {100 * error:.2f} %")
        ax.plot(xs, ps, marker + "-", label=f"{name.replace('_', ' ')}: max error {100 * error:.1f} %")
    ax.axhline(P, color="k", lw=1, label="exact (uniform)")
    ax.set_xlabel("x of the slave node")
    ax.set_ylabel("contact pressure")
    ax.set_title("contact patch test, one-pass node-to-segment, CPE4")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig("contact_patch.png", dpi=100)
    return 0


if __name__ == "__main__":
    sys.exit(main())
