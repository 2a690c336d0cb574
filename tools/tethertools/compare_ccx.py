#!/usr/bin/python3
"""Runs one deck in CalculiX (ccx) and in tether and compares the two .dat files.

    compare_ccx.py DECK.inp [--tether build/bin/tether] [--ccx ccx] [--workdir DIR]
                   [--tether-deck OTHER.inp] [--rtol-u R] [--rtol-rf R] [--rtol-s R] [--rtol-p R]
                   [--atol A] [--timeout S] [--json out.json]

The deck (and the files it *INCLUDEs) is copied into DIR/ccx/ and DIR/tether/
(ccx writes fixed-name scratch files, so each job has its own directory); ccx
runs as `ccx -i JOB`, tether as `tether run JOB.inp -o DIR/tether --dialect calculix`
(the deck is read with CalculiX's meanings where ABAQUS's differ), each under
`/usr/bin/time -v` (peak memory) with a time limit. Both .dat files are parsed
with tools/tethertools/dat.py; blocks are matched by (kind, set, time) -- all common
times, or the last time of each when none is common -- and rows by node id
(elements: element id and integration point). For each quantity the table
gives the count of values compared, the largest |difference|, that difference
relative to the largest |value| of the quantity in ccx's output, and where it
is. See docs/compare_ccx.md for what is compared and why.

Exit status: 0 all differences within tolerance, 1 a difference exceeds its
tolerance, 2 a run failed, ccx is missing or nothing could be compared.
"""
import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import tethertools.dat
import tethertools.deck
import tethertools.sta

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # tools/: the scripts
ROOT = os.path.normpath(os.path.join(TOOLS, ".."))

# Quantities: key -> (label, tolerance option, value columns compared)
QUANTITIES = {
    "U": ("displacement", "rtol_u"),
    "RF": ("reaction (nodal)", "rtol_rf"),
    "RFT": ("reaction (set total)", "rtol_rf"),
    "S": ("stress", "rtol_s"),
    "P": ("contact pressure", "rtol_p"),
}
COMPONENTS = {"U": ("ux", "uy"), "RF": ("fx", "fy"), "RFT": ("fx", "fy"),
              "S": ("sxx", "syy", "szz", "sxy"), "P": ("press",)}


# ----------------------------------------------------------------------------- deck scanning
include_files = tethertools.deck.include_files


class DeckInfo(tethertools.deck.Deck):
    """The deck (tethertools.deck.Deck: mesh, sets, keywords) and what the comparison needs beyond it:
    the nodes under concentrated or pressure loads and the constrained dofs."""

    def __init__(self, deck):
        super().__init__(deck)
        self.cload_nodes, self.pressure_nodes, self.constrained = set(), set(), set()
        for params, data, _ in self.cards:
            kw = params["_kw"]
            if kw == "*BOUNDARY":
                for l in data:
                    v = [x.strip() for x in l.split(",")]
                    if len(v) < 2 or not v[1]:
                        continue
                    first = int(v[1])
                    last = int(v[2]) if len(v) > 2 and v[2] else first
                    for n in self.ids(v[0], self.nsets):
                        for d in range(first, last + 1):
                            if d in (1, 2):
                                self.constrained.add((n, d - 1))
            elif kw == "*CLOAD":
                for l in data:
                    v = [x.strip() for x in l.split(",")]
                    self.cload_nodes.update(self.ids(v[0], self.nsets))
            elif kw in ("*DSLOAD", "*DLOAD"):
                for l in data:
                    v = [x.strip() for x in l.split(",")]
                    if len(v) < 2:
                        continue
                    if kw == "*DSLOAD":
                        for el, face in self.surfaces.get(v[0].upper(), []):
                            self._add_face(str(el), face)
                    elif v[1].upper().startswith("P") and v[1][1:].isdigit():
                        self._add_face(v[0], int(v[1][1:]))

    def _add_face(self, el_token, face):
        for e in self.ids(el_token, self.elsets):
            if e in self.elements:
                self.pressure_nodes.update(self.face_nodes(e, face))

    def family(self):
        fams = {t[:3] for t in self.element_types if t[:3] in ("CPE", "CPS", "CAX")}
        return fams

    def has(self, kw):
        return kw in self.keywords

    def param_values(self, kw, key):
        return [p[key] for p in self.params if p["_kw"] == kw and key in p]


# ----------------------------------------------------------------------------- running
def copy_deck(deck, job, dest):
    os.makedirs(dest, exist_ok=True)
    shutil.copy(deck, os.path.join(dest, job + ".inp"))
    src_dir = os.path.dirname(os.path.abspath(deck))
    for rel in include_files(deck):
        target = os.path.join(dest, rel)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy(os.path.join(src_dir, rel), target)


def run_timed(cmd, cwd, timeout, env=None):
    """Runs `cmd` in `cwd`; returns dict(rc, wall, rss_kb, stdout, stderr, timed_out)."""
    gnu_time = shutil.which("time", path="/usr/bin")
    time_file = os.path.join(cwd, "time.txt")
    full = ([gnu_time, "-v", "-o", time_file] if gnu_time else []) + cmd
    start = time.monotonic()
    proc = subprocess.Popen(full, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    timed_out = False
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        os.killpg(proc.pid, signal.SIGKILL)  # the process group started above, nothing else
        out, err = proc.communicate()
    wall = time.monotonic() - start
    rc = proc.returncode
    rss_kb = None
    if gnu_time and os.path.exists(time_file):
        with open(time_file) as f:
            text = f.read()
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", text)
        rss_kb = int(m.group(1)) if m else None
        m = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", text)
        if m:
            parts = [float(p) for p in m.group(1).split(":")]
            wall = sum(p * 60 ** i for i, p in enumerate(reversed(parts)))
        m = re.search(r"Exit status: (\d+)", text)
        if m:
            rc = int(m.group(1))
    else:
        import resource
        rss_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # max over all children so far
    with open(os.path.join(cwd, "stdout.txt"), "w") as f:
        f.write(out)
    with open(os.path.join(cwd, "stderr.txt"), "w") as f:
        f.write(err)
    return {"rc": rc, "wall": wall, "rss_kb": rss_kb, "stdout": out, "stderr": err, "timed_out": timed_out,
            "measured_by": "/usr/bin/time -v" if gnu_time else "getrusage(RUSAGE_CHILDREN)"}


def kind_of(title):
    t = title.lower()
    if t.startswith("displacements"):
        return "U"
    if t.startswith("total force"):
        return "RFT"
    if t.startswith("forces"):
        return "RF"
    if t.startswith("stresses"):
        return "S"
    if t.startswith("contact stress"):
        return "P"
    return None


def index_blocks(blocks):
    """{(kind, set): {time: block}} (a later block with the same key and time replaces an earlier one)."""
    out = {}
    for b in blocks:
        kind = kind_of(b["title"])
        if kind is None:
            continue
        out.setdefault((kind, b["set"].upper() or "CONTACT"), {})[b["time"]] = b  # "": all contact elements
    return out


def same_time(a, b):
    return abs(a - b) <= 1e-6 * max(1.0, abs(a), abs(b))


def pair_times(ccx_times, tet_times):
    common = [(c, t) for c in sorted(ccx_times) for t in tet_times if same_time(c, t)]
    if common:
        return common, True
    return [(max(ccx_times), max(tet_times))], False


# ----------------------------------------------------------------------------- comparison
class Stat:
    def __init__(self):
        self.count, self.max_abs, self.max_value, self.where = 0, 0.0, 0.0, ""
        self.excluded = 0
        self.notes = set()

    def add(self, ref, val, where):
        self.count += 1
        self.max_value = max(self.max_value, abs(ref))
        d = abs(val - ref)
        if d > self.max_abs or self.count == 1:
            self.max_abs, self.where = d, where

    def rel(self):
        return self.max_abs / self.max_value if self.max_value > 0 else (0.0 if self.max_abs == 0 else float("inf"))


def contact_rows_by_node(rows, max_node, node_labels=()):
    """Contact pressure per 2D node label, layers averaged.

    ccx numbers contact slave nodes in its expanded 3D mesh: the k-th node of
    the sorted label list (k = 1, 2, ...) becomes nk + 3(k-1) + 1..3, nk the
    highest label (measured on ccx 2.20 with gaps in the labels: 2D node 11 of
    labels 1-6, 11-16 became 35..37). Labels up to nk are tether's own rows.
    """
    ordered = sorted(node_labels)
    acc = {}
    for r in rows:
        nid = int(r[0])
        if nid > max_node:
            k = (nid - max_node - 1) // 3
            n2d = ordered[k] if k < len(ordered) else k + 1
        else:
            n2d = nid
        acc.setdefault(n2d, []).append(r[1])
    return {n: sum(v) / len(v) for n, v in acc.items()}


def element_ip_rows(rows):
    out = {}
    for r in rows:
        out.setdefault(int(r[0]), {})[int(r[1])] = r[2:]
    return out


def ccx_ip_for(tet_ip, n_tet, n_ccx, comps_ccx):
    """ccx's stress at tether's integration point `tet_ip` (1-based) of an element.

    ccx's one-layer 3D element numbers its points in-plane first, then through the thickness:
    n_ccx = n_tet (one layer), 2 n_tet (two layers: averaged) or 3 n_tet (the middle layer is used).
    """
    if n_ccx == n_tet:
        return comps_ccx.get(tet_ip)
    if n_ccx == 2 * n_tet:
        a, b = comps_ccx.get(tet_ip), comps_ccx.get(tet_ip + n_tet)
        return None if a is None or b is None else [(x + y) / 2 for x, y in zip(a, b)]
    if n_ccx == 3 * n_tet:
        return comps_ccx.get(tet_ip + n_tet)
    return None


def compare(ccx_blocks, tet_blocks, info, rf_scale):
    stats = {k: Stat() for k in QUANTITIES}
    ci, ti = index_blocks(ccx_blocks), index_blocks(tet_blocks)
    unmatched = []
    for key in sorted(set(ci) | set(ti)):
        kind, set_name = key
        if key not in ci or key not in ti:
            unmatched.append(f"{kind} set {set_name}: only in {'ccx' if key in ci else 'tether'}")
            continue
        pairs, common = pair_times(ci[key].keys(), ti[key].keys())
        if not common:
            stats[kind].notes.add(f"set {set_name}: no common time, compared last times "
                                  f"ccx {pairs[0][0]:g} / tether {pairs[0][1]:g}")
        for tc, tt in pairs:
            cb, tb = ci[key][tc], ti[key][tt]
            where0 = f"set {set_name} t={tt:g}"
            if kind == "U":
                cr = {int(r[0]): r[1:3] for r in cb["rows"]}
                for r in tb["rows"]:
                    n = int(r[0])
                    if n in cr:
                        for k in range(2):
                            stats[kind].add(cr[n][k], r[1 + k], f"{where0} node {n} {COMPONENTS[kind][k]}")
            elif kind == "RF":
                cr = {int(r[0]): r[1:3] for r in cb["rows"]}
                for r in tb["rows"]:
                    n = int(r[0])
                    if n not in cr:
                        continue
                    for k in range(2):
                        if (n, k) not in info.constrained:
                            continue  # free dof: ccx prints the internal force there, tether 0
                        if n in info.cload_nodes or n in info.pressure_nodes:
                            stats[kind].excluded += 1  # RF meaning differs by the applied load
                            continue
                        stats[kind].add(rf_scale * cr[n][k], r[1 + k], f"{where0} node {n} {COMPONENTS[kind][k]}")
            elif kind == "RFT":
                nodes = set(info.nsets.get(set_name, []))
                if nodes & (info.cload_nodes | info.pressure_nodes):
                    stats[kind].excluded += 2
                    stats[kind].notes.add(f"set {set_name}: holds loaded nodes, total not compared")
                    continue
                if not cb["rows"] or not tb["rows"]:
                    continue
                for k in range(2):
                    stats[kind].add(rf_scale * cb["rows"][0][k], tb["rows"][0][k], f"{where0} {COMPONENTS[kind][k]}")
            elif kind == "S":
                ce, te = element_ip_rows(cb["rows"]), element_ip_rows(tb["rows"])
                for e, tips in te.items():
                    if e not in ce:
                        continue
                    n_tet, n_ccx = len(tips), len(ce[e])
                    for ip, vals in tips.items():
                        ref = ccx_ip_for(ip, n_tet, n_ccx, ce[e])
                        if ref is None:
                            stats[kind].excluded += 4
                            stats[kind].notes.add(f"element {e}: {n_tet} tether points vs {n_ccx} ccx points, not matched")
                            continue
                        for k in range(4):
                            stats[kind].add(ref[k], vals[k], f"{where0} elem {e} ip {ip} {COMPONENTS[kind][k]}")
            elif kind == "P":
                cp = contact_rows_by_node(cb["rows"], info.max_node, info.node_labels)
                tp = contact_rows_by_node(tb["rows"], info.max_node, info.node_labels)
                for n, v in tp.items():
                    if n in cp:
                        stats[kind].add(cp[n], v, f"{where0} node {n}")
                    else:
                        stats[kind].excluded += 1
    return stats, unmatched


# ----------------------------------------------------------------------------- modelling differences
def model_differences(info):
    out = []
    types = sorted(info.element_types)
    fams = info.family()
    expansions = {"3": "C3D6", "6": "C3D15", "4": "C3D8 (2x2x2 Gauss, no B-bar)", "4R": "C3D8R", "8": "C3D20 (3x3x3 Gauss)",
                  "8R": "C3D20R (2x2x2 Gauss)"}
    if types:
        desc = ", ".join(f"{t} -> {expansions.get(t[3:], '?')}" for t in types)
        out.append(f"ccx expands every 2D element into a one-layer 3D element ({desc}); results are printed "
                   "at the original 2D node ids. Stresses: ccx's points are matched in-plane to tether's, "
                   "through the thickness averaged (2 layers) or the middle layer (3 layers); sxz, syz not compared.")
    if "CPE" in fams:
        out.append("CPE: the out-of-plane motion of the 3D layer is suppressed; the expansion reproduces plane strain.")
    if "CPS" in fams:
        out.append("CPS: ccx solves a one-layer 3D plate of the section thickness with free faces, which is plane "
                   "stress only in the limit of a thin plate (stiffer at thickness ~ depth; ~1e-4 / 1e-2 difference "
                   "in u / root reactions at thickness = depth/100).")
    if "CAX" in fams:
        out.append("CAX: ccx models a 2-degree wedge (cyclic MPCs): its reactions are per wedge, and so are tether's "
                   "in the calculix dialect (full circle / 180); its mid-side nodes come out ~1e-4 softer than the "
                   "corners at the same radius.")
    out.append("RF: ccx prints the internal nodal force, tether internal force minus applied load: reactions are "
               "compared only at constrained components of nodes without *CLOAD or pressure load; set totals only "
               "for sets without loaded nodes; free components are not compared (ccx prints the internal force).")
    if info.has("*CONTACT PAIR"):
        hard = [p for p in info.params if p["_kw"] == "*SURFACE BEHAVIOR" and
                p.get("PRESSURE-OVERCLOSURE", "").upper() == "HARD"]
        if hard:
            out.append("HARD contact: ccx turns it into a linear penalty K = 50 E (tether enforces it exactly "
                       "with multipliers): expect penetration of order p/K in ccx and pressure differences of that order.")
        types_c = {p.get("TYPE", "NODE TO SURFACE").upper() for p in info.params if p["_kw"] == "*CONTACT PAIR"}
        if "NODE TO SURFACE" in types_c:
            out.append("NODE TO SURFACE (ccx): re-pairs up to iteration 8 then freezes; fails the contact patch test "
                       "(-14..+11 % pressure on CPE4). Contact pressures are mapped from ccx's 3D node ids "
                       "(k-th sorted label -> nk + 3(k-1) + 1..3) back to 2D nodes and averaged.")
        if info.has("*FRICTION"):
            out.append("*FRICTION: ccx reads 'mu, stick slope'; ABAQUS reads the 2nd field differently.")
    if info.has("*TIE"):
        out.append("*TIE on 2D elements generates nothing in ccx 2.20 (no force transmitted).")
    if info.has("*EQUATION") or info.has("*MPC"):
        out.append("*EQUATION/*MPC: ccx eliminates the first (dependent) dof; the constraint force shows only "
                   "in RF at the equation's nodes.")
    nl = any("NLGEOM" in p for p in info.params if p["_kw"] == "*STEP")
    if (nl or info.has("*CONTACT PAIR")) and not info.has("*CONTROLS"):
        out.append("ccx's default convergence tolerances are loose (0.5 % residual, 1 % correction) and the deck "
                   "has no *CONTROLS: nonlinear results may differ by that much.")
    out.append("ccx prints 7 significant digits: no relative difference below ~5e-7 is meaningful.")
    return out


# ----------------------------------------------------------------------------- main
def fmt_mem(kb):
    return "?" if kb is None else f"{kb / 1024:.1f} MB"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("deck")
    ap.add_argument("--tether", default=os.path.join(ROOT, "build", "bin", "tether"))
    ap.add_argument("--ccx", default="ccx")
    ap.add_argument("--workdir", help="where the jobs run (default: a temporary folder, removed afterwards)")
    ap.add_argument("--tether-deck", help="run tether on this deck instead of DECK (e.g. a perturbed copy)")
    ap.add_argument("--rtol-u", type=float, default=1e-4, help="displacements, relative to max |u| (default 1e-4)")
    ap.add_argument("--rtol-rf", type=float, default=1e-3, help="reactions, relative to max |RF| (default 1e-3)")
    ap.add_argument("--rtol-s", type=float, default=1e-3, help="stresses, relative to max |S| (default 1e-3)")
    ap.add_argument("--rtol-p", type=float, default=2e-2, help="contact pressures, relative to max |p| (default 2e-2)")
    ap.add_argument("--atol", type=float, default=0.0, help="absolute allowance added to every tolerance (default 0)")
    ap.add_argument("--timeout", type=float, default=600, help="seconds per run (default 600)")
    ap.add_argument("--threads", type=int, default=1, help="OMP_NUM_THREADS for both codes (default 1)")
    ap.add_argument("--json", help="write the results to this file")
    args = ap.parse_args(argv)

    deck = os.path.abspath(args.deck)
    tether_deck = os.path.abspath(args.tether_deck or args.deck)
    for d in (deck, tether_deck):
        if not os.path.exists(d):
            print(f"error: {d}: no such deck", file=sys.stderr)
            return 2
    ccx = shutil.which(args.ccx)
    ccx = os.path.abspath(ccx) if ccx else None
    if ccx is None:
        print(f"error: '{args.ccx}' not found (Debian package calculix-ccx)", file=sys.stderr)
        return 2
    tether = shutil.which(args.tether) or (args.tether if os.access(args.tether, os.X_OK) else None)
    tether = os.path.abspath(tether) if tether else None
    if tether is None:
        print(f"error: tether program '{args.tether}' not found (build target tether_cli)", file=sys.stderr)
        return 2

    job = os.path.splitext(os.path.basename(deck))[0]
    temp = args.workdir is None
    work = tempfile.mkdtemp(prefix=f"compare_ccx_{job}_") if temp else os.path.abspath(args.workdir)
    try:
        return run(args, deck, tether_deck, job, work, ccx, tether)
    finally:
        if temp:
            shutil.rmtree(work, ignore_errors=True)


def run(args, deck, tether_deck, job, work, ccx, tether):
    ccx_dir, tet_dir = os.path.join(work, "ccx"), os.path.join(work, "tether")
    for d in (ccx_dir, tet_dir):
        shutil.rmtree(d, ignore_errors=True)
    copy_deck(deck, job, ccx_dir)
    copy_deck(tether_deck, job, tet_dir)
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads))

    runs = {}
    runs["ccx"] = run_timed(["timeout", str(int(args.timeout) + 5), ccx, "-i", job], ccx_dir, args.timeout, env)
    runs["tether"] = run_timed([tether, "run", job + ".inp", "-o", tet_dir, "-q", "--dialect", "calculix"], tet_dir,
                               args.timeout, env)
    failed = []
    if runs["ccx"]["rc"] != 0 or "Job finished" not in runs["ccx"]["stdout"]:
        failed.append(f"ccx failed (exit {runs['ccx']['rc']}{', timed out' if runs['ccx']['timed_out'] else ''}); "
                      f"see {ccx_dir}/stdout.txt")
    if runs["tether"]["rc"] != 0:
        failed.append(f"tether failed (exit {runs['tether']['rc']}{', timed out' if runs['tether']['timed_out'] else ''}): "
                      + (runs["tether"]["stderr"].strip().splitlines() or [""])[-1])
    for code, folder in (("ccx", ccx_dir), ("tether", tet_dir)):
        its, _, incs = tethertools.sta.iterations(os.path.join(folder, job + ".sta"))
        runs[code]["iterations"], runs[code]["increments"] = its, incs

    print(f"deck    {deck}" + (f"\ntether  runs {tether_deck}" if tether_deck != deck else ""))
    print(f"work    {work}{' (temporary)' if args.workdir is None else ''}")
    print()
    print(f"{'':8}{'wall [s]':>10}{'peak memory':>14}{'increments':>12}{'Newton its':>12}{'exit':>6}")
    for name in ("ccx", "tether"):
        r = runs[name]
        print(f"{name:8}{r['wall']:10.2f}{fmt_mem(r['rss_kb']):>14}{str(r['increments']):>12}"
              f"{str(r['iterations']):>12}{r['rc']:>6}")
    print(f"(memory: {runs['ccx']['measured_by']}; iterations: sum of ITRS in each .sta)")
    print()

    result = {"deck": deck, "tether_deck": tether_deck, "runs": {k: {kk: v for kk, v in r.items()
                                                                     if kk not in ("stdout", "stderr")}
                                                                 for k, r in runs.items()}}
    if failed:
        for f in failed:
            print("error: " + f, file=sys.stderr)
        result["status"] = "run failed"
        write_json(args, result)
        return 2

    info = DeckInfo(deck)
    fams = info.family()
    # tether runs in the calculix dialect, whose .dat gives CAX forces per 2-degree segment as ccx's does.
    rf_scale = 1.0
    ccx_blocks = tethertools.dat.read(os.path.join(ccx_dir, job + ".dat"))
    tet_blocks = tethertools.dat.read(os.path.join(tet_dir, job + ".dat"))
    stats, unmatched = compare(ccx_blocks, tet_blocks, info, rf_scale)

    tol = {"rtol_u": args.rtol_u, "rtol_rf": args.rtol_rf, "rtol_s": args.rtol_s, "rtol_p": args.rtol_p}
    print("differences tether - ccx (rel = max |diff| / max |ccx value| of the quantity"
          + (", ccx reactions x 180" if rf_scale != 1 else "") + ")")
    print(f"{'quantity':22}{'count':>7}{'max |value|':>13}{'max |diff|':>12}{'rel':>10}{'rtol':>9}  {'':4}  location of max")
    exceeded, compared = [], 0
    result["quantities"] = {}
    for key, (label, tol_name) in QUANTITIES.items():
        s = stats[key]
        if s.count == 0 and s.excluded == 0:
            continue
        compared += s.count
        limit = tol[tol_name] * s.max_value + args.atol
        ok = s.max_abs <= limit
        if not ok:
            exceeded.append(label)
        print(f"{label:22}{s.count:7d}{s.max_value:13.4e}{s.max_abs:12.3e}{s.rel():10.2e}{tol[tol_name]:9.1e}  "
              f"{'ok' if ok else 'FAIL':4}  {s.where}" + (f"  ({s.excluded} excluded)" if s.excluded else ""))
        for note in sorted(s.notes)[:5]:
            print(f"{'':24}note: {note}")
        result["quantities"][key] = {"label": label, "count": s.count, "excluded": s.excluded,
                                     "max_value": s.max_value, "max_abs_diff": s.max_abs, "rel_diff": s.rel(),
                                     "rtol": tol[tol_name], "where": s.where, "ok": ok, "notes": sorted(s.notes)}
    for u in unmatched:
        print(f"not compared: {u}")
    print()
    print("modelling differences (ccx 2.20 vs tether) for this deck:")
    diffs = model_differences(info)
    for d in diffs:
        print("  - " + d)
    result["model_differences"] = diffs
    result["unmatched"] = unmatched
    print()
    if compared == 0:
        print("result: nothing compared (no matching blocks/rows)")
        result["status"] = "nothing compared"
        write_json(args, result)
        return 2
    if exceeded:
        print("result: FAIL (" + ", ".join(exceeded) + " beyond tolerance)")
        result["status"] = "fail"
        write_json(args, result)
        return 1
    print("result: ok (all within tolerance)")
    result["status"] = "ok"
    write_json(args, result)
    return 0


def write_json(args, result):
    if args.json:
        with open(args.json, "w") as f:
            json.dump(result, f, indent=2, default=str)


if __name__ == "__main__":
    sys.exit(main())
