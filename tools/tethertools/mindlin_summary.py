#!/usr/bin/python3
"""Stick zone and tangential traction of a Cattaneo-Mindlin run (deck from tools/make_mindlin_deck.py).

    mindlin_summary.py JOB.dat [JOB2.dat ...] [--label tether --label ccx] [--deck JOB.inp]
                       [--png q.png] [--json out.json]

For each .dat (tether's or CalculiX's; the deck defaults to JOB.inp next to it)
and every increment of the tangential step (total time > 1), from the
*CONTACT PRINT CSTR rows (press, tang1 per slave node; ccx's 3D node ids are
mapped back, tools/tethertools):
  status   stick / slip: tether's `contact state` block (1 = stick, 2 = slip)
           when present, else |tang| < (1 - 1e-3) mu press (ccx: penalty stick,
           a slipping node sits on the Coulomb bound);
  c        the stick-zone half-width: on each side, the midpoint between the
           last node of the stick run that contains x = 0 and the next node;
           the mean of both sides, against c = a sqrt(1 - Q_k / (mu P)) with Q_k
           the tangential load of the increment;
  q(x)     tang (sign: the total is +Q) against Mindlin's
           q = mu p0 (sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2)), |x| < c,
           q = mu p0 sqrt(1 - x^2/a^2), c <= |x| <= a; errors in units of mu p0,
           max over the stick zone (|x| < c) and over the whole strip;
  force    sum of tang x tributary length (lumped) of the slave nodes against Q;
  a        the contact half-width of the last increment: least squares of
           p^2 = p0^2 (1 - x^2/a^2) over the nodes with p >= half the peak
           (tools/hertz_summary.py `figures`; both sides of x = 0), against
           a = sqrt(4 P R / (pi E*)): identical materials, so Q leaves p unchanged.
x is the slave node's reference coordinate (linear theory).
--png plots q(x) / (mu p0) of every run over Mindlin's curve (last increment).
"""
import argparse
import json
import math
import os
import sys

import tethertools.dat
import tethertools.deck
import tethertools.sta
from tethertools import hertz_summary


def mindlin_q(x, a, c, p0, mu):
    q = mu * p0 * math.sqrt(max(0.0, 1.0 - (x / a) ** 2))
    if abs(x) < c:
        q -= mu * p0 * (c / a) * math.sqrt(max(0.0, 1.0 - (x / c) ** 2))
    return q


def stick_half_width(points):
    """points: [(x, stick bool)] -> (c, c_left, c_right) from the stick run through x = 0."""
    sides = []
    for sign in (1.0, -1.0):
        side = sorted((sign * x, s) for x, s in points if sign * x >= -1e-12)
        if not side or not side[0][1]:
            sides.append(0.0)
            continue
        k = 0
        while k + 1 < len(side) and side[k + 1][1]:
            k += 1
        sides.append(0.5 * (side[k][0] + side[k + 1][0]) if k + 1 < len(side) else side[k][0])
    return 0.5 * (sides[0] + sides[1]), sides[1], sides[0]


def summarize(dat, deck_path, label):
    deck = tethertools.deck.Deck(deck_path)
    P, Q, mu = deck.number("P"), deck.number("Q"), deck.number("mu")
    a, p0 = deck.number("a"), deck.number("p0")
    blocks = tethertools.dat.read(dat, strict=False)
    cstr = [b for b in tethertools.dat.blocks_of(blocks, "contact stress") if b["time"] > 1 + 1e-9]
    states = {round(b["time"], 9): b for b in tethertools.dat.blocks_of(blocks, "contact state")}
    lengths = deck.tributary_lengths("SLAVE")
    history = []
    last = None
    for b in cstr:
        rows = tethertools.dat.slave_rows(deck.max_node, b["rows"])
        qk = (b["time"] - 1.0) * Q
        c_exact = a * math.sqrt(max(0.0, 1.0 - qk / (mu * P)))
        state = states.get(round(b["time"], 9))
        if state:
            status = {int(r[0]): int(r[1]) for r in state["rows"]}
            stick = {n: status.get(n, 0) == 1 for n in rows}
            source = "status"
        else:
            stick = {n: p > 0 and abs(t) < (1 - 1e-3) * mu * p for n, (p, t) in rows.items()}
            source = "|tang| < mu press"
        pts = [(deck.xy[n][0], stick[n]) for n in rows]
        c, cl, cr = stick_half_width(pts)
        total = sum(t * lengths.get(n, 0.0) for n, (p, t) in rows.items())
        history.append({"time": b["time"], "Q": qk, "c": c, "c_left": cl, "c_right": cr, "c_exact": c_exact,
                        "c_error": c / c_exact - 1 if c_exact > 0 else float("nan"),
                        "stick_nodes": sum(stick.values()), "tangential_force": abs(total)})
        last = (rows, stick, c_exact, total, source)
    if last is None:
        raise SystemExit(f"{dat}: no contact stress block in the tangential step (total time > 1)")
    rows, stick, c_exact, total, source = last
    pressure = {n: 0.0 for n in deck.nsets.get("SLAVEN", [])}  # ccx prints only its active contact elements
    pressure.update({n: max(0.0, p) for n, (p, t) in rows.items()})
    normal = hertz_summary.figures(sorted((deck.xy[n][0], p) for n, p in pressure.items()), {"a": a, "p0": p0})
    sign = 1.0 if total >= 0 else -1.0
    profile, err_stick, err_all = [], 0.0, 0.0
    for n, (p, t) in sorted(rows.items(), key=lambda kv: deck.xy[kv[0]][0]):
        x = deck.xy[n][0]
        if p <= 0:
            continue
        q = sign * t
        e = abs(q - mindlin_q(x, a, c_exact, p0, mu)) / (mu * p0)
        if abs(x) < c_exact:
            err_stick = max(err_stick, e)
        if abs(x) <= a:
            err_all = max(err_all, e)
        profile.append((x, q, p, bool(stick[n])))
    h = history[-1]
    return {"label": label, "dat": dat, "deck": deck_path, "P": P, "Q": Q, "mu": mu, "a": a, "p0": p0,
            "c_exact": c_exact, "c": h["c"], "c_error": h["c_error"], "status_from": source,
            "q_error_stick": err_stick, "q_error_all": err_all, "tangential_force": h["tangential_force"],
            "tangential_force_error": h["tangential_force"] / Q - 1, "a_fit": normal.get("a_fit"),
            "a_fit_error": normal.get("a_fit_error"), "a_fit_nodes": normal.get("fit_nodes"),
            "peak_error": normal.get("peak_error"), "history": history, "profile": profile}


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    r0 = results[0]
    a, c, p0, mu = r0["a"], r0["c_exact"], r0["p0"], r0["mu"]
    xs = [a * (-1.0 + 2.0 * k / 800) for k in range(801)]
    fig, ax = plt.subplots(figsize=(7.5, 4.5))
    ax.plot([x / a for x in xs], [mindlin_q(x, a, c, p0, mu) / (mu * p0) for x in xs], "k-", lw=1.2,
            label="Mindlin q(x)")
    ax.plot([x / a for x in xs], [math.sqrt(max(0, 1 - (x / a) ** 2)) for x in xs], "k:", lw=0.8,
            label="μ p(x) (Hertz)")
    markers = ["o", "s", "^", "v"]
    for k, r in enumerate(results):
        st = [(x / a, q / (mu * p0)) for x, q, p, s in r["profile"] if s]
        sl = [(x / a, q / (mu * p0)) for x, q, p, s in r["profile"] if not s]
        m = markers[k % len(markers)]
        ax.plot([v[0] for v in st], [v[1] for v in st], m, ms=3.5, mfc="none", color=f"C{k}",
                label=f"{r['label']}: stick (c {100 * r['c_error']:+.1f} %)")
        ax.plot([v[0] for v in sl], [v[1] for v in sl], m, ms=3.5, color=f"C{k}", label=f"{r['label']}: slip")
    for s in (-1, 1):
        ax.axvline(s * c / a, color="0.6", lw=0.6, ls="--")
    ax.set_xlim(-1.15, 1.15)
    ax.set_ylim(-0.05, 1.05)
    ax.set_xlabel("x / a")
    ax.set_ylabel("q / (μ p0)")
    ax.set_title(f"Cattaneo–Mindlin, Q/(μP) = {r0['Q'] / (r0['mu'] * r0['P']):.2g}: "
                 f"stick zone |x| < c = {c / a:.4f} a")
    ax.legend(fontsize=7, loc="lower center", ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("dat", nargs="+")
    ap.add_argument("--label", action="append", default=[])
    ap.add_argument("--deck", action="append", default=[], help="deck of each .dat (default JOB.inp next to it)")
    ap.add_argument("--png")
    ap.add_argument("--json")
    opts = ap.parse_args(argv)
    results = []
    for k, dat in enumerate(opts.dat):
        deck = opts.deck[k] if k < len(opts.deck) else os.path.splitext(dat)[0] + ".inp"
        label = opts.label[k] if k < len(opts.label) else os.path.basename(dat)
        r = summarize(dat, deck, label)
        results.append(r)
        print(f"[ mindlin ] {label}: c {r['c']:.5f} (exact {r['c_exact']:.5f}, {100 * r['c_error']:+.2f} %; "
              f"status from {r['status_from']}), max |q - q_Mindlin| / (mu p0): stick zone {r['q_error_stick']:.4f}, "
              f"whole strip {r['q_error_all']:.4f}, sum of tangential forces {r['tangential_force']:.3f} "
              f"(Q {r['Q']:.6g}, {100 * r['tangential_force_error']:+.3f} %)")
        if r["a_fit"] is not None:
            print(f"[ mindlin ] {label}: contact half-width a {r['a_fit']:.5f} (fit over {r['a_fit_nodes']} nodes; exact "
                  f"{r['a']:.5f}, {100 * r['a_fit_error']:+.2f} %), peak pressure {100 * r['peak_error']:+.2f} % vs p0")
        for h in r["history"]:
            print(f"[ mindlin ]   {label} Q {h['Q']:8.3f}: c {h['c']:.5f} (exact {h['c_exact']:.5f}, "
                  f"{100 * h['c_error']:+.2f} %), {h['stick_nodes']} stick nodes")
    if opts.png:
        plot(results, opts.png)
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump(results, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
