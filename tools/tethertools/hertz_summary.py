#!/usr/bin/python3
"""Contact pressure of a Hertz run (deck from tools/make_hertz_deck.py) against the exact solution.

    hertz_summary.py JOB.dat [MORE.dat ...] [--deck JOB.inp] [--png p.png] [--json out.json]
                     [--time T] [--label ccx [--label tether ...]] [--tol 0.01]
                     [--source auto|cstr|rf|stress]

Reads the .dat with tools/tethertools/dat.py (several: runs of the same deck, e.g. ccx
and tether, plotted together) and the deck (default: JOB.inp next to the first
.dat) for the node coordinates, the slave/master node sets and the model data
written into its *HEADING (R, E, nu, P, rigid_flat). Prints the peak pressure,
the half-width of the contact strip, their errors against the exact plane-strain
Hertz values (tools/hertz_exact.py), the total contact force against P/2 and
the support reaction; --png plots p(x) over the exact curve.

Where the pressure comes from:
  1. the `contact stress (slave node,press,tang1,tang2)` block of *CONTACT PRINT
     CSTR (last time, or --time). ccx numbers its slave nodes in the one-layer 3D
     mesh it expands 2D elements into: 2D node n -> nk + 3 (n - 1) + 1..3, nk =
     the highest node id of the deck. Ids above nk are mapped back that way and
     the layers averaged; every mapped node must be a node of SLAVEN with the
     deck's coordinates (else the tool stops). tether prints the deck's own ids.
     A negative pressure is ccx's tension tail of the penalty law at a small
     clearance (-sigma_inf): the node is open, p = 0.
  2. without a CSTR block, from the nodal forces RF_y on the master nodes
     (MASTERN), each divided by the node's share w = int N dx of the master
     faces (p = f / w; the sign is taken so that the forces push the block
     down: ccx prints the support reaction). This needs the master nodes to
     carry the contact force in RF: true for the rigid flat (its nodes are
     supported); at the free master nodes of the elastic block both codes
     print 0, and the tool goes on to
  3. the internal forces of the block elements under the contact (*EL PRINT S,
     ELSET PRESSEL): f_j = sum over their integration points of B_j^T sigma w
     det J (CPE4 2x2, CPE8 3x3; ccx's one-layer 3D points matched as in
     tools/compare_ccx.py: 2 layers averaged, 3: the middle one). At a master
     node these forces are the contact force on the block (the master's far
     end, shared with elements outside the set, is left out); p = f / w as
     in 2. On the 25k deck they add up to the support reaction (1000.0 N/mm).
Nodes with p > 0 count as in contact (3.: p > 1e-4 of the largest p).
--source cstr|rf|stress forces one of them (default: the first available).

Figures (x = undeformed coordinate of the slave or master node):
  peak     the largest nodal pressure, error vs p0;
  edge     half-width: between the last node in contact (i) and the first open
           one, where the Hertz profile through nodes i-1 and i vanishes (p^2 is
           linear in x^2 for p = p0 sqrt(1 - x^2/a^2)), clamped to [x_i, x_i+1];
  fit      least squares of p^2 = A - B x^2 over the nodes with p >= half the
           peak (x <~ 0.87 a): p0_fit = sqrt(A), a_fit = sqrt(A/B). The last one
           or two nodes before the edge carry a pressure smeared over their
           tributary length (and, from master-side forces, the next node too),
           so they are left out; on the 25k mesh this moves ccx's a from
           +0.53 % (all nodes) to +0.15 %.
  force    the integral of the nodal pressure (interpolated linearly, CPE4, or
           quadratically, CPE8, over each slave or master face) vs P/2, and
           the support reaction total (*NODE PRINT TOTALS=ONLY) vs P/2.
Exit status: 0; 1 with --tol when |peak error| or |fitted a error| exceeds it;
2 no node in contact (no contact pressure at all: the tool stops with a message).
"""
import argparse
import json
import math
import os
import sys

import tethertools.dat
import tethertools.deck
from tethertools import hertz_exact

Deck = tethertools.deck.Deck  # elements {id: (type, nodes)}; face_nodes along the face (corner, mid, corner)


# ----------------------------------------------------------------------------- pressures
pick = tethertools.dat.pick  # the last block (or the one at `time`) with that title and set (None: any set)


def from_cstr(block, deck):
    """{node: pressure} from a CSTR block (ccx's 3D ids mapped back, layers averaged)."""
    slave = set(deck.nsets.get("SLAVEN", []))
    acc = {}
    for row in block["rows"]:
        nid = int(row[0])
        n = (nid - deck.max_node - 1) // 3 + 1 if nid > deck.max_node else nid
        if n not in deck.xy or (slave and n not in slave):
            raise SystemExit(f"contact stress row for node {nid}: maps to node {n}, which is not a slave node of the deck")
        acc.setdefault(n, []).append(row[1])
    return {n: sum(v) / len(v) for n, v in acc.items()}


def from_nodal_forces(block, deck):
    """{node: force on the block, y} from RF_y of the master nodes.

    ccx prints the support reaction (+y under a pushing cylinder); the sign is chosen so that the
    forces push the block down (sum < 0), whatever the code's RF convention.
    """
    rf = {int(r[0]): r[2] for r in block["rows"]}
    sign = -1.0 if sum(rf.values()) > 0 else 1.0
    return {n: sign * f for n, f in rf.items()}


GAUSS = {2: ([-1.0 / math.sqrt(3.0), 1.0 / math.sqrt(3.0)], [1.0, 1.0]),
         3: ([-math.sqrt(0.6), 0.0, math.sqrt(0.6)], [5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])}


def shape_derivatives(xi, eta, n):
    """dN/dxi, dN/deta of the 4-node bilinear or 8-node serendipity quad (ABAQUS node order)."""
    if n == 4:
        sx, sy = [-1, 1, 1, -1], [-1, -1, 1, 1]
        return ([sx[i] * (1 + sy[i] * eta) / 4 for i in range(4)], [sy[i] * (1 + sx[i] * xi) / 4 for i in range(4)])
    sx, sy = [-1, 1, 1, -1], [-1, -1, 1, 1]
    dxi, deta = [], []
    for i in range(4):  # corners
        dxi.append(sx[i] * (1 + sy[i] * eta) * (2 * sx[i] * xi + sy[i] * eta) / 4)
        deta.append(sy[i] * (1 + sx[i] * xi) * (sx[i] * xi + 2 * sy[i] * eta) / 4)
    for i, (mx, my) in enumerate([(0, -1), (1, 0), (0, 1), (-1, 0)]):  # mid-sides
        if mx == 0:
            dxi.append(-xi * (1 + my * eta))
            deta.append(my * (1 - xi * xi) / 2)
        else:
            dxi.append(mx * (1 - eta * eta) / 2)
            deta.append(-eta * (1 + mx * xi))
    return dxi, deta


def from_stresses(block, deck):
    """{node: f_y} internal forces of the PRESSEL elements at their nodes, from their integration-point stresses.

    f_j = sum over points of B_j^T sigma w det J (plane strain, thickness 1): at a master node, which
    belongs to PRESSEL elements only (inside x < c), this is the contact force on the block.
    """
    per_element = {}
    for row in block["rows"]:
        per_element.setdefault(int(row[0]), {})[int(row[1])] = (row[2], row[3], row[5])  # sxx, syy, sxy
    force = {}
    for el, ips in per_element.items():
        etype, conn = deck.elements[el]
        nn = len(conn)
        n_2d = 4 if nn == 4 else 9
        per_dir = 2 if n_2d == 4 else 3
        n = len(ips)
        if n == n_2d:
            sig = [ips[k + 1] for k in range(n_2d)]
        elif n == 2 * n_2d:
            sig = [tuple((u + v) / 2.0 for u, v in zip(ips[k + 1], ips[k + 1 + n_2d])) for k in range(n_2d)]
        elif n == 3 * n_2d:
            sig = [ips[k + 1 + n_2d] for k in range(n_2d)]
        else:
            raise SystemExit(f"element {el}: {n} integration points, expected {n_2d}, {2 * n_2d} or {3 * n_2d}")
        xy = [deck.xy[c] for c in conn]
        pts, wts = GAUSS[per_dir]
        for k in range(n_2d):
            xi, eta = pts[k % per_dir], pts[k // per_dir]  # xi fastest (tether's and ccx's order)
            w = wts[k % per_dir] * wts[k // per_dir]
            dxi, deta = shape_derivatives(xi, eta, nn)
            j11 = sum(d * p[0] for d, p in zip(dxi, xy))
            j12 = sum(d * p[1] for d, p in zip(dxi, xy))
            j21 = sum(d * p[0] for d, p in zip(deta, xy))
            j22 = sum(d * p[1] for d, p in zip(deta, xy))
            det = j11 * j22 - j12 * j21
            sxx, syy, sxy = sig[k]
            for i, node in enumerate(conn):
                dndx = (j22 * dxi[i] - j12 * deta[i]) / det
                dndy = (-j21 * dxi[i] + j11 * deta[i]) / det
                force[node] = force.get(node, 0.0) + (dndx * sxy + dndy * syy) * w * det
    # a node shared with an element outside the set (the master's far end, x = c) has an incomplete sum
    inside = set(per_element)
    shared = {n for el, (_, conn) in deck.elements.items() if el not in inside for n in conn if n in force}
    return {n: f for n, f in force.items() if n not in shared}


def lumped_pressure(deck, faces, force_y):
    """{node: p} = -f_y / w with w = int N dx over the faces (force on the block: -y under pressure)."""
    weight = {}
    for el, face in faces:
        fn = deck.face_nodes(el, face)
        length = abs(deck.xy[fn[-1]][0] - deck.xy[fn[0]][0])
        shares = [0.5, 0.5] if len(fn) == 2 else [1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0]
        for node, share in zip(fn, shares):
            weight[node] = weight.get(node, 0.0) + share * length
    return {n: -force_y.get(n, 0.0) / w for n, w in weight.items() if w > 0}


def integrate(deck, faces, pressure):
    """Integral of the nodal pressure over the faces (linear / quadratic interpolation in x)."""
    total = 0.0
    for el, face in faces:
        fn = deck.face_nodes(el, face)
        if not all(n in pressure for n in fn):
            continue
        length = abs(deck.xy[fn[-1]][0] - deck.xy[fn[0]][0])
        if len(fn) == 2:
            total += length * (pressure[fn[0]] + pressure[fn[1]]) / 2.0
        else:
            total += length * (pressure[fn[0]] + 4.0 * pressure[fn[1]] + pressure[fn[2]]) / 6.0
    return total


# ----------------------------------------------------------------------------- figures
def figures(points, exact, threshold=0.0):
    """points: sorted [(x, p)] with p >= 0; in contact: p > threshold. Returns the peak, edge and fit figures."""
    a, p0 = exact["a"], exact["p0"]
    contact = [(x, p) for x, p in points if p > threshold]
    out = {"nodes": len(points), "nodes_in_contact": len(contact)}
    if not contact:
        return out
    xpk, ppk = max(contact, key=lambda t: t[1])
    out.update(peak=ppk, peak_x=xpk, peak_error=ppk / p0 - 1.0)
    # edge: last contact node i, first open node after it
    last = max(k for k, (x, p) in enumerate(points) if p > threshold)
    xi, pi = points[last]
    x_open = points[last + 1][0] if last + 1 < len(points) else None
    if last >= 1 and points[last - 1][1] > pi:
        xm, pm = points[last - 1]
        x2 = xi * xi + pi * pi * (xi * xi - xm * xm) / (pm * pm - pi * pi)
        edge = math.sqrt(max(x2, 0.0))
    else:
        edge = xi
    edge = max(edge, xi)
    if x_open is not None:
        edge = min(edge, x_open)
    out.update(edge=edge, edge_error=edge / a - 1.0, last_contact_x=xi, first_open_x=x_open)
    upper = [(x, p) for x, p in contact if p >= 0.5 * ppk]
    fitted = upper if len(upper) >= 2 else contact
    if len(fitted) >= 2:
        n = len(fitted)
        out["fit_nodes"] = n
        sx = sum(x * x for x, _ in fitted)
        sy = sum(p * p for _, p in fitted)
        sxx = sum(x ** 4 for x, _ in fitted)
        sxy = sum(x * x * p * p for x, p in fitted)
        den = n * sxx - sx * sx
        if den > 0:
            slope = (n * sxy - sx * sy) / den
            A = (sy - slope * sx) / n
            B = -slope
            if A > 0 and B > 0:
                out.update(p0_fit=math.sqrt(A), a_fit=math.sqrt(A / B),
                           p0_fit_error=math.sqrt(A) / p0 - 1.0, a_fit_error=math.sqrt(A / B) / a - 1.0)
    return out


def summarise(dat, deck_path=None, time=None, source="auto"):
    deck_path = deck_path or os.path.splitext(dat)[0] + ".inp"
    deck = Deck(deck_path)
    rigid = deck.heading.get("rigid_flat", "0") == "1"
    exact = hertz_exact.hertz(deck.number("P", hertz_exact.P), deck.number("R", hertz_exact.R),
                              deck.number("E", hertz_exact.E), deck.number("nu", hertz_exact.NU), rigid)
    half = exact["P"] / 2.0
    blocks = tethertools.dat.read(dat)  # ccx's and tether's contact headers
    result = {"dat": os.path.abspath(dat), "deck": os.path.abspath(deck_path), "exact": exact,
              "element": deck.heading.get("element"), "dofs": int(deck.number("dofs", 2 * len(deck.xy)))}
    tried = []
    points = None
    threshold = 0.0
    if source in ("auto", "cstr"):
        cstr = pick(blocks, "contact stress", None, time)
        if cstr is not None:
            pressure = from_cstr(cstr, deck)
            for n in deck.nsets.get("SLAVEN", []):
                pressure.setdefault(n, 0.0)  # ccx prints only its active contact elements
            pressure = {n: max(0.0, p) for n, p in pressure.items()}
            points = sorted((deck.xy[n][0], p) for n, p in pressure.items())
            force = integrate(deck, deck.surfaces.get("SLAVE", []), pressure)
            result.update(source="CSTR", time=cstr["time"])
        else:
            tried.append("no contact stress block")
    if points is None and source in ("auto", "rf"):
        rf = pick(blocks, "forces", "MASTERN", time)
        if rf is not None and sum(abs(r[2]) for r in rf["rows"]) > 1e-3 * half:
            faces = deck.surfaces.get("MASTER", [])
            pressure = {n: max(0.0, p) for n, p in lumped_pressure(deck, faces, from_nodal_forces(rf, deck)).items()}
            points = sorted((deck.xy[n][0], p) for n, p in pressure.items())
            force = integrate(deck, faces, pressure)
            result.update(source="RF on MASTERN", time=rf["time"])
        else:
            tried.append("no contact force in RF of MASTERN" if rf is not None else "no forces block for MASTERN")
    if points is None and source in ("auto", "stress"):
        st = pick(blocks, "stresses", "PRESSEL", time)
        if st is not None:
            faces = deck.surfaces.get("MASTER", [])
            pressure = {n: max(0.0, p) for n, p in lumped_pressure(deck, faces, from_stresses(st, deck)).items()}
            points = sorted((deck.xy[n][0], p) for n, p in pressure.items())
            force = integrate(deck, faces, pressure)
            threshold = 1e-4 * max(p for _, p in points) if points else 0.0
            result.update(source="element forces of PRESSEL", time=st["time"])
        else:
            tried.append("no stresses block for PRESSEL")
    if points is None:
        raise SystemExit(f"{dat}: no contact pressure found ({'; '.join(tried)})")
    result.update(figures(points, exact, threshold))
    result["points"] = points
    result.update(contact_force=force, contact_force_error=force / half - 1.0)
    for name in ("BOTTOM", "NBLOCK"):
        tot = pick(blocks, "total force", name, time)
        if tot is not None and tot["rows"]:
            result.update(support=name, support_force=tot["rows"][0][1], support_error=tot["rows"][0][1] / half - 1.0)
            break
    return result


def pct(v):
    return "-" if v is None else f"{100 * v:+.2f} %"


def report(r, label=""):
    ex = r["exact"]
    case = "rigid flat" if ex["rigid_flat"] else "elastic block"
    print(f"Hertz {case}{' (' + label + ')' if label else ''}: {r['dat']}  [{r['element']}, {r['dofs']} dofs, "
          f"pressure from {r['source']}, time {r['time']:g}]")
    print(f"  exact     a = {ex['a']:.5g} mm   p0 = {ex['p0']:.5g} MPa   (E* = {ex['Estar']:.6g} MPa, P/2 = {ex['P'] / 2:g} N/mm)")
    if "peak" not in r:
        print("  no node in contact")
        return
    print(f"  peak      p = {r['peak']:.5g} MPa at x = {r['peak_x']:.4g}   error {pct(r['peak_error'])}")
    print(f"  edge      a = {r['edge']:.5g} mm   error {pct(r['edge_error'])}   (last node in contact x = "
          f"{r['last_contact_x']:.4g}, first open x = {r['first_open_x'] if r['first_open_x'] is None else round(r['first_open_x'], 4)})")
    if "a_fit" not in r:
        print("  fit       not possible (p^2 does not decrease linearly in x^2 over the nodes with p >= peak/2)")
    else:
        print(f"  fit       p0 = {r['p0_fit']:.5g} MPa ({pct(r['p0_fit_error'])})   a = {r['a_fit']:.5g} mm ({pct(r['a_fit_error'])})"
              f"   over the {r['fit_nodes']} nodes with p >= peak/2 ({r['nodes_in_contact']} in contact)")
    print(f"  force     integral of p = {r['contact_force']:.5g} N/mm ({pct(r['contact_force_error'])} vs P/2)"
          + (f"   support {r['support']} = {r['support_force']:.5g} ({pct(r['support_error'])})" if "support" in r else ""))


def plot(results, png, labels=None):
    """p(x) of one run or several runs of the same case (a list) over the exact curve."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np
    results = results if isinstance(results, list) else [results]
    labels = labels if isinstance(labels, list) else [labels or ""] * len(results)
    ex = results[0]["exact"]
    a, p0 = ex["a"], ex["p0"]
    xs = np.linspace(0.0, 1.6 * a, 400)
    fig, ax = plt.subplots(figsize=(7, 4.2))
    ax.plot(xs, hertz_exact.pressure(xs, a, p0), "k-", lw=1.2, label=f"exact (a = {a:.4g} mm, p0 = {p0:.4g} MPa)")
    peak = p0
    for r, label, marker in zip(results, labels, "osd^v<>"):
        pts = [(x, p) for x, p in r["points"] if x <= 1.6 * a]
        ax.plot([x for x, _ in pts], [p for _, p in pts], marker, ms=4, mfc="none",
                label=f"{label or 'FE'} ({r['element']}, {r['dofs']} dofs, {r['source']}): "
                      f"peak {pct(r.get('peak_error'))}, a (fit) {pct(r.get('a_fit_error'))}")
        peak = max(peak, r.get("peak", 0.0))
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("contact pressure [MPa]")
    ax.set_title(f"plane-strain Hertz, {'rigid flat' if ex['rigid_flat'] else 'elastic block'}, P = {ex['P']:g} N/mm")
    ax.set_xlim(0, 1.6 * a)
    ax.set_ylim(0, 1.15 * peak)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("dat", nargs="+", help="one .dat, or several runs of the same deck (one plot)")
    ap.add_argument("--deck", help="the deck (default: JOB.inp next to the first JOB.dat)")
    ap.add_argument("--time", type=float, help="step time of the blocks to use (default: the last)")
    ap.add_argument("--png", help="plot p(x) over the exact curve into this PNG")
    ap.add_argument("--json", help="write the figures (and the points) to this JSON file (one run)")
    ap.add_argument("--label", action="append", default=[], help="name of the code, once per .dat (printout, plot)")
    ap.add_argument("--source", default="auto", choices=["auto", "cstr", "rf", "stress"],
                    help="where the pressure comes from (default: CSTR, else RF on MASTERN, else stresses)")
    ap.add_argument("--tol", type=float, help="exit 1 when |peak error| or |fitted a error| exceeds this (e.g. 0.01)")
    args = ap.parse_args(argv)
    labels = args.label + [""] * (len(args.dat) - len(args.label))
    deck = args.deck or os.path.splitext(args.dat[0])[0] + ".inp"
    results = []
    for dat, label in zip(args.dat, labels):
        r = summarise(dat, deck, args.time, args.source)
        report(r, label)
        results.append(r)
    if args.png:
        plot(results, args.png, labels)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results[0] if len(results) == 1 else results, f, indent=2)
    status = 0
    for r in results:
        if "peak" not in r:
            status = 2
        elif args.tol is not None and (abs(r["peak_error"]) > args.tol or abs(r.get("a_fit_error", math.inf)) > args.tol):
            status = max(status, 1)
    return status


if __name__ == "__main__":
    sys.exit(main())
