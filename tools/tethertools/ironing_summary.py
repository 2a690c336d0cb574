#!/usr/bin/python3
"""Driving forces of an ironing run (deck from tools/make_ironing_deck.py): Fx / Fy against mu.

    ironing_summary.py JOB.dat [JOB2.dat ...] [--label L ...] [--deck JOB.inp] [--steady 1.0]
                       [--png ratio.png] [--json out.json]

For each .dat (tether's or CalculiX's; deck: JOB.inp next to it, .sta: JOB.sta
next to it) reads the `total force (fx,fy,fz) for set TOPN` blocks (*NODE PRINT,
TOTALS=ONLY, RF of the driven top nodes of the die) of the slide step (total
time t > 1; slide distance s = (t - 1) S) and prints per increment
Fx, Fy, Fx / |Fy| and the Newton iterations of the increment (the .sta's ITRS
of the converged attempt; failed attempts are counted separately). Steady
sliding: s >= --steady (default 1 mm, several contact widths; up to the .dat's
7-digit times, so an increment at exactly 1 mm counts). Reports the mean,
min and max of Fx / |Fy| over it against mu (deck heading), and for mu = 0 the
largest |Fx| / |Fy|. --png plots Fx / |Fy| and the iterations per increment
against s for the runs with mu > 0, and 1000 Fx / |Fy| for the mu = 0 runs.
"""
import argparse
import json
import os
import sys

import tethertools.dat
import tethertools.deck
import tethertools.sta


def summarize(dat, deck_path, sta_path, label, steady):
    deck = tethertools.deck.Deck(deck_path)
    mu, slide = deck.number("mu"), deck.number("slide")
    blocks = tethertools.dat.blocks_of(tethertools.dat.read(dat, strict=False), "total force", "TOPN")
    sta = tethertools.sta.read(sta_path) if os.path.exists(sta_path) else []
    converged = [r for r in sta if r[4]]
    failed = [r for r in sta if not r[4]]
    # converged increments in file order; the i-th force block of the run is the i-th converged increment
    history = []
    for k, b in enumerate(blocks):
        fx, fy = b["rows"][0][0], b["rows"][0][1]
        t = b["time"]
        its = converged[k][3] if k < len(converged) else None
        step = converged[k][0] if k < len(converged) else (1 if t <= 1 + 1e-9 else 2)
        history.append({"time": t, "step": step, "slide": max(0.0, t - 1.0) * slide, "Fx": fx, "Fy": fy,
                        "ratio": fx / abs(fy) if fy else float("nan"), "iterations": its})
    sliding = [h for h in history if h["time"] > 1 + 1e-9]
    # the .dat's times have 7 digits: the increment at exactly `steady` may read as slide 0.9999990
    window = [h for h in sliding if h["slide"] >= steady - 1e-6 * max(1.0, slide)]
    ratios = [h["ratio"] for h in window]
    out = {"label": label, "dat": dat, "deck": deck_path, "mu": mu, "slide": slide, "history": history,
           "steady_from": steady, "steady_increments": len(window),
           "iterations_max": max((h["iterations"] or 0) for h in history) if sta else None,
           "iterations_total": sum(r[3] for r in sta) if sta else None, "failed_attempts": len(failed)}
    if ratios:
        out.update(ratio_mean=sum(ratios) / len(ratios), ratio_min=min(ratios), ratio_max=max(ratios),
                   Fy_mean=sum(h["Fy"] for h in window) / len(window))
        if mu > 0:
            out["ratio_error_max"] = max(abs(r / mu - 1) for r in ratios)
            out["ratio_worst"] = max(ratios, key=lambda r: abs(r / mu - 1))  # signed, farthest from mu
        else:
            out["ratio_abs_max"] = max(abs(r) for r in ratios)
    return out


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    frictional = [r for r in results if r["mu"] > 0]
    frictionless = [r for r in results if r["mu"] == 0]
    panels = (2 if frictional else 0) + (1 if frictionless else 0)
    fig, axes = plt.subplots(panels, 1, figsize=(7.5, 2.9 * panels), squeeze=False, sharex=True)
    axes = list(axes[:, 0])

    def sliding(r, key, scale=1.0):
        hs = [h for h in r["history"] if h["time"] > 1 + 1e-9 and h[key] is not None]
        return [h["slide"] for h in hs], [scale * h[key] for h in hs]

    if frictional:
        ax = axes.pop(0)
        mu = frictional[0]["mu"]
        ax.axhspan(0.98 * mu, 1.02 * mu, color="0.9", label="μ ± 2 %")
        ax.axhline(mu, color="k", lw=0.8, label=f"μ = {mu:g}")
        ax.axvline(frictional[0]["steady_from"], color="0.5", lw=0.8, ls=":",
                   label=f"steady sliding from {frictional[0]['steady_from']:g} mm")
        for k, r in enumerate(frictional):
            x, y = sliding(r, "ratio")
            ax.plot(x, y, "-", lw=0.7, color=f"C{k}", label=r["label"])
        ax.set_ylim(0.97 * mu, 1.03 * mu)
        ax.set_ylabel("Fx / |Fy|")
        ax.legend(fontsize=7, loc="upper right", ncol=2)
        ax.set_title("Ironing: driving force ratio and Newton iterations against slide distance")
        ax = axes.pop(0)
        for k, r in enumerate(frictional):
            x, y = sliding(r, "iterations")
            ax.plot(x, y, ".", ms=3, color=f"C{k}", label=r["label"])
        ax.axhline(8, color="k", lw=0.8, ls="--", label="8 (bound)")
        most = max([8] + [h["iterations"] or 0 for r in frictional for h in r["history"]])
        ax.set_ylim(0, 1.45 * most)  # room for the legend above the points
        ax.set_ylabel("iterations / increment")
        ax.legend(fontsize=7, loc="upper right")
    if frictionless:
        ax = axes.pop(0)
        for k, r in enumerate(frictionless):
            x, y = sliding(r, "ratio", 1000.0)
            ax.plot(x, y, "s-", ms=2.5, lw=0.7, color=f"C{k + len(frictional)}", label=r["label"])
        ax.axhline(0, color="k", lw=0.8)
        ax.set_ylabel("1000 Fx / |Fy|  (μ = 0)")
        ax.legend(fontsize=7)
    fig.axes[-1].set_xlabel("slide distance [mm]")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("dat", nargs="+")
    ap.add_argument("--label", action="append", default=[])
    ap.add_argument("--deck", action="append", default=[])
    ap.add_argument("--steady", type=float, default=1.0, help="steady sliding from this slide distance [mm]")
    ap.add_argument("--png")
    ap.add_argument("--json")
    opts = ap.parse_args(argv)
    results = []
    for k, dat in enumerate(opts.dat):
        base = os.path.splitext(dat)[0]
        deck = opts.deck[k] if k < len(opts.deck) else base + ".inp"
        label = opts.label[k] if k < len(opts.label) else os.path.basename(dat)
        r = summarize(dat, deck, base + ".sta", label, opts.steady)
        results.append(r)
        for h in r["history"]:
            print(f"[ ironing ]   {label} step {h['step']} t {h['time']:.4f} slide {h['slide']:7.3f}: Fx {h['Fx']:12.5g} "
                  f"Fy {h['Fy']:12.5g} Fx/|Fy| {h['ratio']:+.5f}  iterations {h['iterations']}")
        if "ratio_mean" in r:
            extra = (f"max |ratio/mu - 1| {100 * r['ratio_error_max']:.3f} %" if r["mu"] > 0
                     else f"max |Fx/Fy| {r['ratio_abs_max']:.2e}")
            print(f"[ ironing ] {label}: mu {r['mu']:g}, steady sliding ({r['steady_increments']} increments, "
                  f"slide >= {r['steady_from']:g} mm): Fx/|Fy| mean {r['ratio_mean']:.5f} "
                  f"[{r['ratio_min']:.5f}, {r['ratio_max']:.5f}], {extra}, Fy {r['Fy_mean']:.5g}; "
                  f"iterations max {r['iterations_max']} total {r['iterations_total']}, "
                  f"failed attempts {r['failed_attempts']}")
    if opts.png:
        plot(results, opts.png)
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump(results, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
