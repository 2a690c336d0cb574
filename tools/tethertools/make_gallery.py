#!/usr/bin/python3
"""Verification gallery: regenerates docs/verification.md and its figures.

    /usr/bin/python3 tools/make_gallery.py [--tether build/bin/tether] [--ccx ccx] [--out docs]
                                           [--workdir DIR] [--json FILE] [--quick]

For every benchmark the decks are written by the project's generators
(tools/make_lame_deck.py, tools/make_cantilever_deck.py, examples/periodic_rve/make_deck.py,
the patch-test deck below) into a work folder, run with tether (and with CalculiX where ccx can
run the case: the patch tests, Lame CPE4/CPE8/CAX8 and the cantilever CPE8 / thin CPS8), the
.dat files are read with tools/tethertools/dat.py and compared with the exact answer. Writes
OUT/verification.md and OUT/images/verification/*.png; --json FILE also writes the numbers
(used by the smoke test tests/tools/gallery_test.py). Contact: Hertz (examples/hertz), the contact
patch test (examples/contact_patch), a friction block, and the decks of the Cattaneo-Mindlin and
ironing tests (tools/make_mindlin_deck.py, tools/make_ironing_deck.py with the tests' options,
summarised by tools/mindlin_summary.py and tools/ironing_summary.py; ccx runs a copy with a
penalty stick slope). Those two take most of the time, in ccx above all (25-30 s each on an
idle 2-core machine, up to ~2 min on a loaded one): --quick runs them in tether only (the smoke
test's setting; the ccx columns of the other cases are filled as usual). Needs numpy, matplotlib,
meshio (Debian python3-*) and gmsh.

Exit status: 0 every tether error within its stated tolerance, 1 one is not (or a run failed),
2 usage error (tether not found).
"""
import argparse
import datetime
import glob
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

from tethertools import compare_ccx
import tethertools.dat
import tethertools.sta
from tethertools import make_cantilever_deck as cantilever
from tethertools import make_lame_deck as lame
import matplotlib

TOOLS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # tools/: the scripts
ROOT = os.path.normpath(os.path.join(TOOLS, ".."))

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PY = sys.executable


# ----------------------------------------------------------------------------- running
class Runner:
    def __init__(self, tether, ccx, work, timeout=120):
        self.tether, self.ccx, self.work, self.timeout = tether, ccx, work, timeout

    def _job(self, deck):
        return os.path.splitext(os.path.basename(deck))[0]

    def run_tether(self, deck, timeout=None):
        job = self._job(deck)
        d = os.path.join(self.work, job, "tether")
        shutil.rmtree(d, ignore_errors=True)
        compare_ccx.copy_deck(deck, job, d)
        r = compare_ccx.run_timed([self.tether, "run", job + ".inp", "-o", d, "-q"], d, timeout or self.timeout,
                                  dict(os.environ, OMP_NUM_THREADS="1"))
        r["iterations"], _, r["increments"] = tethertools.sta.iterations(os.path.join(d, job + ".sta"))
        r["dir"] = d
        r["blocks"] = tethertools.dat.read(os.path.join(d, job + ".dat")) if r["rc"] == 0 else None
        if r["rc"] != 0:
            print(f"error: tether failed on {deck} (exit {r['rc']}): {r['stderr'].strip()[-300:]}", file=sys.stderr)
        return r

    def run_ccx(self, deck, timeout=None):
        if not self.ccx:
            return None
        job = self._job(deck)
        d = os.path.join(self.work, job, "ccx")
        shutil.rmtree(d, ignore_errors=True)
        compare_ccx.copy_deck(deck, job, d)
        limit = timeout or self.timeout
        r = compare_ccx.run_timed(["timeout", str(limit + 5), self.ccx, "-i", job], d, limit,
                                  dict(os.environ, OMP_NUM_THREADS="1"))
        r["dir"] = d
        r["iterations"], _, r["increments"] = tethertools.sta.iterations(os.path.join(d, job + ".sta"))
        ok = r["rc"] == 0 and "Job finished" in r["stdout"]
        r["blocks"] = tethertools.dat.read(os.path.join(d, job + ".dat")) if ok else None
        if not ok:
            print(f"warning: ccx failed on {deck} (exit {r['rc']})", file=sys.stderr)
        return r


def ccx_failure(c):
    """Why a ccx run gave no results, in words for the notes (None: it did)."""
    if c is None or c["blocks"]:
        return None
    if c["timed_out"]:
        return f"ccx did not finish within the gallery's time limit ({c['wall']:.0f} s)"
    return f"ccx stopped with exit status {c['rc']} (no 'Job finished')"


def generate(script, out, args, cwd=None):
    subprocess.run([PY, script, out] + args, check=True, cwd=cwd, stdout=subprocess.DEVNULL)
    return out


def last(blocks, title, set_name):
    return tethertools.dat.last_block(blocks, title, set_name)


def row(case, quantity, exact, tet, tet_err, tol, how, ccx=None, ccx_err=None, ccx_tol=None, ccx_note=None,
        tet_run=None, ccx_run=None):
    """One table row (errors are relative, signed where that means something)."""
    def figures(r):
        if r is None:
            return None
        return {"wall": r["wall"], "iterations": r["iterations"], "increments": r["increments"], "rc": r["rc"]}
    return {"case": case, "quantity": quantity, "exact": exact, "tether": tet, "tether_error": tet_err,
            "tolerance": tol, "ccx": ccx, "ccx_error": ccx_err, "ccx_tolerance": ccx_tol, "ccx_note": ccx_note,
            "tether_run": figures(tet_run), "ccx_run": figures(ccx_run), "how": how}


# ----------------------------------------------------------------------------- patch test
PATCH_NODES = {1: (0.0, 0.0), 2: (0.24, 0.0), 3: (0.24, 0.12), 4: (0.0, 0.12),
               5: (0.04, 0.02), 6: (0.18, 0.03), 7: (0.16, 0.08), 8: (0.08, 0.08)}
PATCH_QUADS = [(1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (4, 1, 5, 8), (5, 6, 7, 8)]
PATCH_E, PATCH_NU, PATCH_G = 1.0e6, 0.25, 1.0e-3   # u = G (x + y/2), v = G (y + x/2)


def patch_u(x, y):
    return PATCH_G * (x + y / 2), PATCH_G * (y + x / 2)


def patch_exact_stress(etype):
    e, nu = PATCH_E, PATCH_NU
    exx = eyy = PATCH_G
    gxy = PATCH_G
    mu = e / (2 * (1 + nu))
    if etype.startswith("CPS"):
        c = e / (1 - nu * nu)
        return [c * (exx + nu * eyy), c * (eyy + nu * exx), 0.0, mu * gxy]
    lam = e * nu / ((1 + nu) * (1 - 2 * nu))
    sxx, syy = lam * (exx + eyy) + 2 * mu * exx, lam * (exx + eyy) + 2 * mu * eyy
    return [sxx, syy, nu * (sxx + syy), mu * gxy]


def write_patch_deck(path, etype):
    """MacNeal-Harder constant-strain patch (0.24 x 0.12, 5 distorted quads, or 10 triangles):
    the linear field u = G (x + y/2), v = G (y + x/2) is prescribed on every boundary node."""
    nodes = dict(PATCH_NODES)
    quadratic = etype[3] in "68"
    tri = etype[3] in "36"
    mids = {}

    def mid(a, b):
        key = (min(a, b), max(a, b))
        if key not in mids:
            n = max(nodes) + 1
            nodes[n] = tuple((p + q) / 2 for p, q in zip(nodes[a], nodes[b]))
            mids[key] = n
        return mids[key]

    elements = []
    for q in PATCH_QUADS:
        polys = [q] if not tri else [(q[0], q[1], q[2]), (q[0], q[2], q[3])]
        for p in polys:
            conn = list(p)
            if quadratic:
                conn += [mid(p[k], p[(k + 1) % len(p)]) for k in range(len(p))]
            elements.append(conn)
    boundary = [n for n, (x, y) in nodes.items()
                if min(abs(x), abs(x - 0.24), abs(y), abs(y - 0.12)) < 1e-12]
    lines = ["*HEADING", f"Constant-strain patch test (MacNeal-Harder), {etype}", "*NODE, NSET=NALL"]
    lines += [f"{n}, {x:.15g}, {y:.15g}" for n, (x, y) in sorted(nodes.items())]
    lines.append(f"*ELEMENT, TYPE={etype}, ELSET=EALL")
    lines += [f"{k}, " + ", ".join(map(str, c)) for k, c in enumerate(elements, 1)]
    lines += ["*NSET, NSET=BND", ", ".join(map(str, sorted(boundary))),
              "*MATERIAL, NAME=M", "*ELASTIC", f"{PATCH_E:g}, {PATCH_NU:g}",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "1.", "*STEP", "*STATIC", "1., 1.", "*BOUNDARY"]
    for n in sorted(boundary):
        u, v = patch_u(*nodes[n])
        lines += [f"{n}, 1, 1, {u:.15g}", f"{n}, 2, 2, {v:.15g}"]
    lines += ["*NODE PRINT, NSET=NALL", "U", "*EL PRINT, ELSET=EALL", "S", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return nodes


def patch_errors(blocks, etype, nodes):
    ex = patch_exact_stress(etype)
    scale = max(abs(v) for v in ex)
    s = last(blocks, "stresses", "EALL")
    err_s = max(abs(r[2 + k] - ex[k]) for r in s["rows"] for k in range(4)) / scale
    u = last(blocks, "displacements", "NALL")
    uscale = max(max(abs(c) for c in patch_u(*xy)) for xy in nodes.values())
    err_u = max(abs(r[1 + k] - patch_u(*nodes[int(r[0])])[k]) for r in u["rows"] for k in range(2)) / uscale
    return err_s, err_u


def bench_patch(rn):
    rows = []
    ex_note = None
    for etype in ("CPE4", "CPS4", "CPE3", "CPE8", "CPE6"):
        deck = os.path.join(rn.work, f"patch_{etype.lower()}.inp")
        nodes = write_patch_deck(deck, etype)
        t = rn.run_tether(deck)
        c = rn.run_ccx(deck) if etype in ("CPE4", "CPE8") else None
        ex = patch_exact_stress(etype)
        ex_note = ex
        te = patch_errors(t["blocks"], etype, nodes) if t["blocks"] else (float("nan"), float("nan"))
        ce = patch_errors(c["blocks"], etype, nodes) if c and c["blocks"] else None
        sx = last(t["blocks"], "stresses", "EALL")["rows"][0][2] if t["blocks"] else None
        cx = last(c["blocks"], "stresses", "EALL")["rows"][0][2] if ce else None
        rows.append(row(f"patch {etype}", "max |σ − σ_exact| / max |σ_exact| (σxx shown)", ex[0], sx, te[0], 1e-5,
                        f"`patch_{etype.lower()}.inp`: 8-node MacNeal–Harder patch ({'10 triangles' if etype[3] in '36' else '5 quads'}"
                        f"{', mid-side nodes at edge midpoints' if etype[3] in '68' else ''}), boundary nodes "
                        "prescribed u = 1e-3 (x + y/2), v = 1e-3 (y + x/2); error over every integration point and "
                        "component", cx, ce[0] if ce else None, 1e-5 if ce else None,
                        None if etype in ("CPE4", "CPE8") else "not run (the gallery runs ccx on CPE4/CPE8 only)",
                        t, c))
        rows.append(row(f"patch {etype}", "max |u − u_exact| / max |u| (all nodes)", None, None, te[1], 1e-5,
                        "same run: displacements of every node (interior ones are free)",
                        None, ce[1] if ce else None, 1e-5 if ce else None,
                        None if etype in ("CPE4", "CPE8") else "not run"))
    return rows


# ----------------------------------------------------------------------------- Lame
def lame_exact_ur(r, plane_stress=False):
    a, b, p, e, nu = lame.A, lame.B, lame.P, lame.E, lame.NU
    if plane_stress:
        c, d = p * a * a / (b * b - a * a), p * a * a * b * b / (b * b - a * a)
        return ((1 - nu) * c * r + (1 + nu) * d / r) / e
    return (1 + nu) * p * a * a / (e * (b * b - a * a)) * ((1 - 2 * nu) * r + b * b / r)


def bore_ur(blocks, axi):
    rows = last(blocks, "displacements", "INNER")["rows"]
    return [r[1] if axi else math.hypot(r[1], r[2]) for r in rows]


LAME_CASES = [  # type, nr, nt, ccx, tolerance (about 3x the measured error, see the comments)
    ("CPE4", 8, 16, True, 1e-2),     # measured -0.33 %
    ("CPE3", 8, 16, False, 5e-2),    # measured -2.8 %
    ("CPE8", 4, 8, True, 3e-4),      # measured -7.3e-5
    ("CPE6", 4, 8, False, 3e-3),     # measured -0.068 %
    ("CAX8", 4, 1, True, 3e-4),      # measured -6.3e-5
    ("CPS8", 4, 8, False, 3e-4),     # measured -6.0e-5
]


def bench_lame(rn, images):
    rows, profiles = [], {}
    exact = {False: lame_exact_ur(lame.A), True: lame_exact_ur(lame.A, True)}
    for etype, nr, nt, with_ccx, tol in LAME_CASES:
        name = f"lame_{etype.lower()}_{nr}x{nt}"
        deck = generate(os.path.join(TOOLS, "make_lame_deck.py"), os.path.join(rn.work, name + ".inp"),
                        ["--type", etype, "--nr", str(nr), "--nt", str(nt)])
        axi, ps = etype.startswith("CAX"), etype.startswith("CPS")
        ex = exact[ps]
        t = rn.run_tether(deck)
        c = rn.run_ccx(deck) if with_ccx else None

        def worst(blocks):
            vals = bore_ur(blocks, axi)
            i = max(range(len(vals)), key=lambda k: abs(vals[k] / ex - 1))
            return sum(vals) / len(vals), vals[i] / ex - 1

        tv, te = worst(t["blocks"]) if t["blocks"] else (None, float("nan"))
        cv, ce = worst(c["blocks"]) if c and c["blocks"] else (None, None)
        geom = f"{nr}x{nt} ({'slice r∈[10,20], z∈[0,2], u_z = 0 top and bottom' if axi else 'quarter ring, symmetry edges'})"
        rows.append(row(f"Lamé {etype} {nr}x{nt}", "u_r at the bore r = a (mean; error: worst node)", ex, tv, te, tol,
                        f"`tools/make_lame_deck.py --type {etype} --nr {nr} --nt {nt}`: {geom}, p = 100 on the bore, "
                        f"E = 200000, ν = 0.3; {'plane stress' if ps else 'plane strain'} exact u_r(a)",
                        cv, ce, max(tol, 1e-3) if with_ccx else None,
                        None if with_ccx else ("not run: ccx's CPS is a one-layer plate, plane stress only when thin"
                                               if ps else "not run (the gallery runs ccx on Lamé CPE4/CPE8/CAX8)"),
                        t, c))
        if etype in ("CPE8", "CPE4") and t["blocks"]:
            vtus = sorted(glob.glob(os.path.join(t["dir"], "*.vtu")))
            if vtus:
                profiles[f"{etype} {nr}x{nt}"] = vtus[-1]
    plot_lame(profiles, os.path.join(images, "lame_profiles.png"))
    return rows


def plot_lame(profiles, out):
    import meshio
    a, b, p = lame.A, lame.B, lame.P
    fig, ax = plt.subplots(figsize=(7, 4.2))
    r = np.linspace(a, b, 200)
    k = p * a * a / (b * b - a * a)
    ax.plot(r, k * (1 + b * b / r ** 2), "k-", lw=1.2, label="exact σθθ")
    ax.plot(r, k * (1 - b * b / r ** 2), "k--", lw=1.2, label="exact σrr")
    for (label, vtu), mk in zip(sorted(profiles.items()), ("o", "s")):
        m = meshio.read(vtu)
        xy, s = m.points[:, :2], m.point_data["S"]
        rr = np.hypot(xy[:, 0], xy[:, 1])
        c, sn = xy[:, 0] / rr, xy[:, 1] / rr
        s_rr = s[:, 0] * c * c + s[:, 1] * sn * sn + 2 * s[:, 3] * c * sn
        s_tt = s[:, 0] * sn * sn + s[:, 1] * c * c - 2 * s[:, 3] * c * sn
        ax.plot(rr, s_tt, mk, ms=3.5, mfc="none", label=f"tether {label} σθθ (nodal)")
        ax.plot(rr, s_rr, mk, ms=3.5, label=f"tether {label} σrr (nodal)")
    ax.set_xlabel("r [mm]")
    ax.set_ylabel("stress [MPa]")
    ax.set_title("Lamé cylinder, p = 100: stresses through the wall")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=2)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


# ----------------------------------------------------------------------------- cantilever
CANTILEVER_CASES = [  # type, nx, ny, tolerance (tests/verification/cantilever_test.cpp, measured errors)
    ("CPS8", 10, 1, 1.5e-2), ("CPS8", 20, 2, 1e-2), ("CPS8", 40, 4, 5e-3),
    ("CPS4", 10, 2, 0.35), ("CPS4", 20, 4, 0.12), ("CPS4", 40, 8, 0.04), ("CPS4", 80, 16, 1.2e-2),
]


def beam_exact(etype):
    if etype.startswith("CPE"):  # plane strain: E' = E/(1-nu^2), nu' = nu/(1-nu) keeps G
        nu = cantilever.NU
        return cantilever.tip_deflection(10.0, young=cantilever.E / (1 - nu * nu), poisson=nu / (1 - nu))
    return cantilever.tip_deflection(10.0)


def tip_v(blocks):
    return last(blocks, "displacements", "TIPMID")["rows"][0][2]


def bench_cantilever(rn, images):
    rows, conv = [], {}
    cases = [(t, nx, ny, None, tol) for t, nx, ny, tol in CANTILEVER_CASES]
    cases += [("CPE8", 20, 2, 1.0, 1e-2), ("CPS8", 20, 2, 0.01, 1e-2)]  # also run in ccx
    for etype, nx, ny, thick, tol in cases:
        name = f"cantilever_{etype.lower()}_{nx}x{ny}" + ("" if thick is None else f"_t{thick:g}")
        args = ["--type", etype, "--nx", str(nx), "--ny", str(ny)] + ([] if thick is None else ["--thickness", f"{thick:g}"])
        deck = generate(os.path.join(TOOLS, "make_cantilever_deck.py"), os.path.join(rn.work, name + ".inp"), args)
        ex = beam_exact(etype)
        t = rn.run_tether(deck)
        c = rn.run_ccx(deck) if thick is not None else None
        tv = tip_v(t["blocks"]) if t["blocks"] else None
        cv = tip_v(c["blocks"]) if c and c["blocks"] else None
        te = tv / ex - 1 if tv is not None else float("nan")
        if thick is None and tv is not None:
            conv.setdefault(etype, []).append((nx, te))
        rows.append(row(f"cantilever {etype} {nx}x{ny}" + ("" if thick is None else f", T = {thick:g}"),
                        "tip deflection on the axis (TIPMID)", ex, tv, te, tol,
                        f"`tools/make_cantilever_deck.py {' '.join(args)}`: L = 10, H = 1, clamped root, parabolic "
                        f"end shear P = 100 per unit thickness; exact: Timoshenko beam (k = 5/6"
                        + (", plane strain E/(1−ν²), ν/(1−ν)" if etype.startswith("CPE") else ", plane stress") + ")",
                        cv, cv / ex - 1 if cv is not None else None, 1e-2 if thick is not None else None,
                        None if thick is not None else "not run (ccx's CPS is plane stress only as a thin plate: see the T = 0.01 row)",
                        t, c))
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for etype, mk in (("CPS4", "s-"), ("CPS8", "o-")):
        pts = conv.get(etype, [])
        if pts:
            ax.loglog([p[0] for p in pts], [abs(p[1]) * 100 for p in pts], mk, label=f"tether {etype}")
    ax.axhline(0.19, color="gray", ls=":", label="2D clamped beam vs beam theory (−0.19 %)")
    ax.set_xlabel("elements along the length (L/H = 10; depth refined with it)")
    ax.set_ylabel("|tip deflection / Timoshenko − 1|  [%]")
    ax.set_title("Cantilever under end shear: convergence")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(images, "cantilever_convergence.png"), dpi=110)
    plt.close(fig)
    return rows


# ----------------------------------------------------------------------------- rigid link
def bench_rigid_link(rn, images):
    deck = os.path.join(ROOT, "examples", "rigid_link", "rigid_link.inp")
    t = rn.run_tether(deck)
    x0, y0, p = 0.34729635533386083, -1.969615506024416, 3.0
    thetas, lams = [], []
    if t["blocks"]:
        us = [b for b in t["blocks"] if b["title"].startswith("displacements") and b["set"] == "B"]
        ms = [b for b in t["blocks"] if b["title"].startswith("constraint multipliers") and b["set"] == "LINK"]
        for ub, mb in zip(us, ms):
            x, y = x0 + ub["rows"][0][1], y0 + ub["rows"][0][2]
            thetas.append(math.asin(-y / math.hypot(x, y)))
            lams.append(mb["rows"][0][3])
    errs = [lam * math.sin(th) / p - 1 for th, lam in zip(thetas, lams)]
    worst = max(errs, key=abs) if errs else float("nan")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    th = np.linspace(math.radians(8), math.radians(80), 200)
    ax.plot(np.degrees(th), p / np.sin(th), "k-", label="exact N = P / sin θ")
    ax.plot(np.degrees(thetas), lams, "o", mfc="none", label="tether λ (20 increments)")
    ax.set_xlabel("θ [deg]")
    ax.set_ylabel("link force N")
    ax.set_title(f"Rigid link under large rotation: max |λ/N − 1| = {abs(worst):.1e}")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(images, "rigid_link.png"), dpi=110)
    plt.close(fig)
    how = ("`examples/rigid_link/rigid_link.inp`: *MPC LINK (Lagrange), B driven from θ ≈ 78° to 10° in 20 "
           "increments under P = 3, NLGEOM; θ from B's position in the .dat, λ from the multiplier block")
    rows = [row("rigid link, all 20 increments", "link force λ (worst increment; value at θ = 10°)",
                p / math.sin(math.radians(10)), lams[-1] if lams else None, worst, 2e-6, how,
                ccx_note="not run (the gallery runs ccx on the patch, Lamé and cantilever cases only)", tet_run=t)]
    return rows


# ----------------------------------------------------------------------------- periodic RVE
def bench_rve(rn):
    folder = os.path.join(rn.work, "rve")
    os.makedirs(folder, exist_ok=True)
    subprocess.run([PY, os.path.join(ROOT, "examples", "periodic_rve", "make_deck.py")], cwd=folder, check=True)
    deck = os.path.join(folder, "laminate_rve.inp")
    t = rn.run_tether(deck)
    fa, ea, eb, strain = 6 / 16, 1000.0, 100.0, 1e-3
    along_ex, across_ex = fa * ea + (1 - fa) * eb, 1 / (fa / ea + (1 - fa) / eb)
    along = across = None
    if t["blocks"]:
        forces = [b for b in t["blocks"] if b["title"].startswith("forces") and b["set"] == "REF"]
        along = {int(r[0]): r for r in forces[0]["rows"]}[1001][1] / strain
        across = {int(r[0]): r for r in forces[-1]["rows"]}[1002][2] / strain
    how = ("`examples/periodic_rve/make_deck.py`: 16x16 CPE4 cell, 6/16 of E = 1000, the rest E = 100, ν = 0, "
           "*PERIODIC with reference nodes 1001/1002; step 1 H11 = 1e-3, step 2 H22 = 1e-3; modulus = reaction / strain")
    note = "not run: *PERIODIC is a tether keyword"
    return [row("laminate RVE, along the layers", "E_x = f_A E_A + f_B E_B", along_ex, along,
                along / along_ex - 1 if along else float("nan"), 1e-5, how, ccx_note=note, tet_run=t),
            row("laminate RVE, across the layers", "E_y = (f_A/E_A + f_B/E_B)⁻¹", across_ex, across,
                across / across_ex - 1 if across else float("nan"), 1e-5, "same run, step ACROSS", ccx_note=note)]


# ----------------------------------------------------------------------------- contact
def friction_block_deck(path, mu=0.3, p=10.0, slide=0.05, increments=50):
    """A 1 x 0.5 block (4 x 1 CPE4, E = 1000, nu = 0.3) pressed by p onto a rigid flat
    (a 6 x 2 block with every node fixed), then its top edge pushed by `slide` in x."""
    out = ["*HEADING", "friction block on a rigid flat", "*NODE"]
    top = lambda i, j: 1 + j * 5 + i
    bot = lambda i, j: 1001 + j * 7 + i
    out += [f"{top(i, j)}, {i / 4:.17g}, {1 + 0.5 * j:.17g}" for j in range(2) for i in range(5)]
    out += [f"{bot(i, j)}, {2 * i / 6:.17g}, {j / 2:.17g}" for j in range(3) for i in range(7)]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=TOP"] + [f"{1 + i}, {top(i, 0)}, {top(i + 1, 0)}, {top(i + 1, 1)}, {top(i, 1)}"
                                                 for i in range(4)]
    out += ["*ELEMENT, TYPE=CPE4, ELSET=BOTTOM"] + [
        f"{1001 + j * 6 + i}, {bot(i, j)}, {bot(i + 1, j)}, {bot(i + 1, j + 1)}, {bot(i, j + 1)}"
        for j in range(2) for i in range(6)]
    out += ["*SURFACE, NAME=SLAVE"] + [f"{1 + i}, S1" for i in range(4)]
    out += ["*SURFACE, NAME=MASTER"] + [f"{1007 + i}, S3" for i in range(6)]
    out += ["*SURFACE INTERACTION, NAME=I", "*FRICTION", f"{mu:g}",
            "*CONTACT PAIR, INTERACTION=I, TYPE=NODE TO SURFACE", "SLAVE, MASTER",
            "*MATERIAL, NAME=M", "*ELASTIC", "1000, 0.3",
            "*SOLID SECTION, ELSET=TOP, MATERIAL=M", "*SOLID SECTION, ELSET=BOTTOM, MATERIAL=M",
            "*NSET, NSET=BASE, GENERATE", "1001, 1021", "*NSET, NSET=PUSHED"] + [str(top(i, 1)) for i in range(5)]
    out += ["*BOUNDARY", "BASE, 1, 2", "PUSHED, 1",
            "*STEP", "*STATIC", "1, 1", "*DLOAD"] + [f"{1 + i}, P3, {p:g}" for i in range(4)]
    out += ["*END STEP", f"*STEP, INC={10 * increments}", "*STATIC, DIRECT", f"{1 / increments:.17g}, 1",
            "*BOUNDARY", f"PUSHED, 1, 1, {slide:g}", "*NODE PRINT, NSET=PUSHED, TOTALS=ONLY", "RF",
            "*CONTACT PRINT", "CSTR", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return path


def contact_stress_extreme(blocks, deck_path, exact):
    """The nodal contact pressure farthest from `exact` in the last 'contact stress' block
    (ccx's expanded 3D node ids mapped back to the deck's labels)."""
    stress = [b for b in blocks or [] if b["title"].startswith("contact stress")]
    if not stress:
        return None
    info = compare_ccx.DeckInfo(deck_path)
    by_node = compare_ccx.contact_rows_by_node(stress[-1]["rows"], info.max_node, info.node_labels)
    return max(by_node.values(), key=lambda p: abs(p - exact)) if by_node else None


def bench_contact(rn, images):
    from tethertools import hertz_summary  # (needs only the standard library and matplotlib)
    rows = []
    # Hertz: the 2k-dof deck of examples/hertz.
    deck = os.path.join(ROOT, "examples", "hertz", "hertz.inp")
    t, c = rn.run_tether(deck), rn.run_ccx(deck)
    job = rn._job(deck)
    st = hertz_summary.summarise(os.path.join(t["dir"], job + ".dat"), deck) if t["blocks"] else None
    sc = None
    if c and c["blocks"]:
        try:
            sc = hertz_summary.summarise(os.path.join(rn.work, job, "ccx", job + ".dat"), deck)
        except SystemExit as e:
            print(f"warning: ccx Hertz: {e}", file=sys.stderr)
    if st and sc:
        hertz_summary.plot([st, sc], os.path.join(images, "hertz_2k.png"),
                           ["tether", "CalculiX (HARD -> penalty 50 E)"])
    elif st:
        hertz_summary.plot([st], os.path.join(images, "hertz_2k.png"), ["tether"])
    how = ("`examples/hertz/hertz.inp` (`tools/make_hertz_deck.py --dofs 2k`): half model, CPE4, h = a/4 at the "
           "contact, pure load control in 10 increments; HARD contact (ccx: penalty K = 50 E); fit p² = p0²(1 − x²/a²) "
           "over the nodes with p ≥ peak/2; the 25k-dof case (within 1 %) is tests/verification/hertz_test.cpp")
    for quantity, key, exact_key, tol in (("peak nodal pressure", "peak", "p0", 0.01),
                                          ("fitted half-width a", "a_fit", "a", 0.01)):
        exact = st["exact"][exact_key] if st else float("nan")
        tv = st.get(key, float("nan")) if st else float("nan")
        cv = sc.get(key) if sc else None
        rows.append(row("Hertz, 2k dofs", quantity, exact, tv, tv / exact - 1, tol, how, ccx=cv,
                        ccx_err=(cv / exact - 1) if cv is not None else None, ccx_tol=0.02 if cv is not None else None,
                        tet_run=t, ccx_run=c))
        how = "same runs"
    # Contact patch test: one-pass node-to-segment on non-matching meshes (a method limit, documented).
    folder = os.path.join(rn.work, "contact_patch")
    os.makedirs(folder, exist_ok=True)
    subprocess.run([PY, os.path.join(ROOT, "examples", "contact_patch", "make_deck.py")], cwd=folder, check=True,
                   stdout=subprocess.DEVNULL)
    for name, label, bound in (("fine_on_coarse", "slave finer (7 on 4)", 0.06),
                               ("coarse_on_fine", "slave coarser (4 on 6)", 0.16)):
        deck = os.path.join(folder, name + ".inp")
        t, c = rn.run_tether(deck), rn.run_ccx(deck)
        tv = contact_stress_extreme(t["blocks"], deck, 10.0)
        cv = contact_stress_extreme(c["blocks"] if c else None, deck, 10.0)
        rows.append(row(f"contact patch test, {label}", "nodal pressure farthest from p (uniform p = 10)", 10.0,
                        tv if tv is not None else float("nan"), (tv / 10 - 1) if tv is not None else float("nan"),
                        bound, "`examples/contact_patch/make_deck.py`: CPE4 blocks, one-pass node-to-segment; "
                        "the tolerance is the documented error of the method, not a pass", ccx=cv,
                        ccx_err=(cv / 10 - 1) if cv is not None else None, ccx_tol=bound if cv is not None else None,
                        tet_run=t, ccx_run=c))
    # Friction block: full slip at T = mu N.
    deck = friction_block_deck(os.path.join(rn.work, "friction_block.inp"))
    t = rn.run_tether(deck)
    ratio = float("nan")
    if t["blocks"]:
        fx = abs(last(t["blocks"], "total force", "PUSHED")["rows"][0][0])
        stress = [b for b in t["blocks"] if b["title"].startswith("contact stress")][-1]
        areas = {1: 0.125, 2: 0.25, 3: 0.25, 4: 0.25, 5: 0.125}  # tributary lengths of the slave nodes
        normal = sum(r[1] * areas[int(r[0])] for r in stress["rows"])
        ratio = fx / (0.3 * normal)
    rows.append(row("friction block", "push force / (mu N) in full slip", 1.0, ratio, ratio - 1, 1e-6,
                    "a 4-element CPE4 block pressed by p = 10 onto a rigid flat and pushed along it by 0.05 in 50 "
                    "increments, mu = 0.3, exact stick by multipliers; N from the CSTR pressures x tributary lengths",
                    ccx_note="not compared (ccx's friction is a stick penalty)", tet_run=t))
    return rows


# ----------------------------------------------------------------------------- frictional contact
# The decks of tests/verification/mindlin_test.cpp and ironing_test.cpp, written by the same generators
# with the same options. ccx has no exact stick: it runs a copy written with "*FRICTION mu, K" (penalty
# stick slope K = 50 E, as its HARD contact is a penalty 50 E); given mu alone it falls back to a stick
# slope of 1e5, much softer. With --quick (the smoke test) only tether runs these two cases.
STICK_SLOPE = "1e7"
QUICK_NOTE = "not run with --quick (the smoke test leaves out ccx's long runs; the full regeneration runs it)"
LONG_TIMEOUT = 900  # s, a run: ccx needs about 0.5-2 min for each of these decks on the shared 2-core machine


def frictional_runs(rn, script, name, options, quick):
    """Writes the deck (and, unless quick or without ccx, the ccx copy with a stick slope), runs them.
    Returns (deck, tether run, ccx deck, ccx run, ccx note)."""
    deck = generate(script, os.path.join(rn.work, name + ".inp"), options)
    t = rn.run_tether(deck, LONG_TIMEOUT)
    if quick:
        return deck, t, None, None, QUICK_NOTE
    if not rn.ccx:
        return deck, t, None, None, None
    ccx_deck = generate(script, os.path.join(rn.work, name + "_ccx.inp"), options + ["--stick-slope", STICK_SLOPE])
    c = rn.run_ccx(ccx_deck, LONG_TIMEOUT)
    return deck, t, ccx_deck, c, ccx_failure(c)


def run_files(run, deck):
    """JOB.dat and JOB.sta of a run of `deck` (None when it gave no results)."""
    if not run or not run["blocks"]:
        return None
    base = os.path.join(run["dir"], os.path.splitext(os.path.basename(deck))[0])
    return base + ".dat", base + ".sta"


def bench_mindlin(rn, images, quick):
    import tethertools.dat
    import tethertools.deck
    import tethertools.sta
    from tethertools import make_mindlin_deck
    from tethertools import mindlin_summary
    options = ["--element", "CPE4"]
    deck, t, ccx_deck, c, note = frictional_runs(rn, os.path.join(TOOLS, "make_mindlin_deck.py"), "mindlin_cpe4",
                                                 options, quick)
    info = tethertools.deck.Deck(deck)
    ex = make_mindlin_deck.mindlin(info.number("P"), info.number("Q"), info.number("mu"), info.number("R"),
                                   info.number("E"), info.number("nu"))
    ratio = info.number("Q") / (info.number("mu") * info.number("P"))
    files = run_files(t, deck)
    st = mindlin_summary.summarize(files[0], deck, "tether (exact stick)") if files else None
    files = run_files(c, ccx_deck)
    sc = mindlin_summary.summarize(files[0], ccx_deck, f"CalculiX (stick slope {STICK_SLOPE})") if files else None
    plotted = [r for r in (st, sc) if r]
    if plotted:
        mindlin_summary.plot(plotted, os.path.join(images, "cattaneo_mindlin.png"))

    def value(r, key):
        return r.get(key) if r else None

    def worst_c(r):
        return max((h["c_error"] for h in r["history"]), key=abs) if r else None

    def tet(v):
        return float("nan") if v is None else v

    ccx_tol = {"a": 5e-3 if sc else None, "c": 0.05 if sc else None}
    case = f"Cattaneo–Mindlin, {info.number('dofs') / 1000:.1f}k dofs"
    how = (f"`tools/make_mindlin_deck.py {' '.join(options)}` (the deck of tests/verification/mindlin_test.cpp): "
           f"half cylinder R = {info.number('R'):g} mm on a block, both E = {info.number('E'):g}, ν = "
           f"{info.number('nu'):g}, CPE4, full model, h = a/{ex['a'] / info.number('h'):.0f} at the contact; the "
           f"cylinder's flat top translates rigidly (*EQUATION); step 1 P = {info.number('P'):g} N/mm in 10 "
           f"increments, step 2 Q = {ratio:g} μP in 5, the "
           f"cylinder held in x by friction alone; HARD, *FRICTION μ = {info.number('mu'):g} (tether: exact stick by "
           "a multiplier). Exact (identical materials: the normal and tangential problems decouple): "
           "a = √(4PR/(πE*)), E* = E/(2(1−ν²)). a measured: least squares of p² = p0²(1 − x²/a²) over the nodes "
           "with p ≥ peak/2 at the end of step 2. ccx: the same deck written with "
           f"`--stick-slope {STICK_SLOPE}` (`*FRICTION` {info.number('mu'):g}, {STICK_SLOPE}: penalty stick of slope "
           "50 E; ccx has no exact stick, and given μ alone it takes a stick slope of 1e5, far softer, and sticks "
           "over a much wider zone), HARD → penalty 50 E")
    return [row(case, "contact half-width a (fit of p², end of step 2)", ex["a"], tet(value(st, "a_fit")),
                tet(value(st, "a_fit_error")), 5e-3, how, ccx=value(sc, "a_fit"), ccx_err=value(sc, "a_fit_error"),
                ccx_tol=ccx_tol["a"], ccx_note=note, tet_run=t, ccx_run=c),
            row(case, f"stick-zone half-width c at Q = {ratio:g} μP", ex["c"], tet(value(st, "c")),
                tet(value(st, "c_error")), 0.05,
                "same runs: c = a√(1 − Q/(μP)) with the exact a; measured from the slave nodes' stick/slip status "
                "(ccx prints none: there a node sticks when |τ| < (1 − 10⁻³) μp): on each side the midpoint between "
                "the last node of the stick run through x = 0 and the next node, both sides averaged, so it resolves "
                f"c to ±h/2 = ±{50 * info.number('h') / ex['c']:.1f} %; tolerance 5 %. The figure shows q(x) "
                "over Mindlin's q = μp0(√(1 − x²/a²) − (c/a)√(1 − x²/c²)) in the stick zone, μp outside",
                ccx=value(sc, "c"), ccx_err=value(sc, "c_error"), ccx_tol=ccx_tol["c"], ccx_note=note),
            row(case, "c at each of the 5 increments of Q (worst error)", None, None, tet(worst_c(st)), 0.05,
                f"same runs, every increment of step 2, Q = {ratio / 5:g} … {ratio:g} μP (the test checks each)",
                ccx_err=worst_c(sc), ccx_tol=ccx_tol["c"], ccx_note=note)]


def bench_ironing(rn, images, quick):
    import tethertools.dat
    import tethertools.deck
    import tethertools.sta
    from tethertools import ironing_summary
    options = ["--mu", "0.3", "--slide", "3", "--slide-increments", "24"]
    steady = 1.0  # mm: steady sliding from here (as the test)
    deck, t, ccx_deck, c, note = frictional_runs(rn, os.path.join(TOOLS, "make_ironing_deck.py"),
                                                 "ironing_cpe4_mu03_slide3", options, quick)
    info = tethertools.deck.Deck(deck)
    mu = info.number("mu")

    def summary(run, d, label):
        files = run_files(run, d)
        if not files:
            return None
        r = ironing_summary.summarize(files[0], d, files[1], label, steady)
        return r if "ratio_mean" in r else None

    st = summary(t, deck, "tether (exact stick)")
    sc = summary(c, ccx_deck, f"CalculiX (stick slope {STICK_SLOPE})")
    plotted = [r for r in (st, sc) if r]
    if plotted:
        ironing_summary.plot(plotted, os.path.join(images, "ironing_3mm.png"))

    def over_mu(r, key):
        return r[key] / mu if r else None

    def err(v):
        return None if v is None else v - 1

    def tet(v):
        return float("nan") if v is None else v

    window = "; ".join(f"{r['label'].split()[0]}: {r['steady_increments']} increments" for r in plotted)
    case = f"ironing, μ = {mu:g}, {info.number('slide'):g} mm slide, {info.number('dofs') / 1000:.1f}k dofs"
    how = (f"`tools/make_ironing_deck.py {' '.join(options)}` (the deck of tests/verification/ironing_test.cpp "
           f"`Ironing.Cpe4FrictionRatioIsMu`): a die (half disc Rd = {info.number('Rd'):g}, the block's material "
           f"E = {info.number('E'):g}, ν = {info.number('nu'):g}) pressed {info.number('indent'):g} mm into a block "
           f"in 4 increments, then slid {info.number('slide'):g} mm over master segments of "
           f"{info.number('master_size'):g} mm in 24 increments, CPE4, NLGEOM, HARD, *FRICTION μ = {mu:g} (tether: "
           "exact stick). Exact: every contact node slips and the pressure is symmetric about the die axis "
           "(identical materials), so Fx/|Fy| = μ for the reaction totals of the driven top nodes (TOPN). Steady "
           f"sliding: slide ≥ {steady:g} mm ({window or 'no run'}); tolerance 2 %. ccx: the same deck "
           f"written with `--stick-slope {STICK_SLOPE}` (`*FRICTION` {mu:g}, {STICK_SLOPE}: penalty stick, it has "
           "no exact one), HARD → penalty 50 E. The frictionless case (Fx → 0) is "
           "tests/verification/ironing_test.cpp `Ironing.Cpe4FrictionlessHasNoDrag`")
    mean_t, mean_c = over_mu(st, "ratio_mean"), over_mu(sc, "ratio_mean")
    worst_t, worst_c = over_mu(st, "ratio_worst"), over_mu(sc, "ratio_worst")
    return [row(case, "Fx/(μ|Fy|), mean over steady sliding", 1.0, tet(mean_t), tet(err(mean_t)), 0.02, how,
                ccx=mean_c, ccx_err=err(mean_c), ccx_tol=0.02 if sc else None, ccx_note=note, tet_run=t, ccx_run=c),
            row(case, "Fx/(μ|Fy|), steady-sliding increment farthest from 1", 1.0, tet(worst_t), tet(err(worst_t)),
                0.02, "same runs (the test checks every steady increment); the figure shows Fx/|Fy| and the Newton "
                "iterations of every slide increment", ccx=worst_c, ccx_err=err(worst_c),
                ccx_tol=0.02 if sc else None, ccx_note=note)]


# ----------------------------------------------------------------------------- report
def fmt(v, digits=7):
    if v is None:
        return "—"
    if isinstance(v, float) and math.isnan(v):
        return "failed"
    return f"{v:.{digits}g}"


def fmt_err(e):
    if e is None:
        return "—"
    if math.isnan(e):
        return "failed"
    return f"{e * 100:+.2g} %" if abs(e) >= 1e-4 else f"{e:+.1e}"


def fmt_run(r):
    if not r:
        return "—"
    its = "?" if r["iterations"] is None else r["iterations"]
    return f"{r['wall']:.2f} s / {its}"


SECTIONS = [("patch", "Constant-strain patch tests"), ("lame", "Lamé thick cylinder under internal pressure"),
            ("cantilever", "Cantilever under end shear (Timoshenko beam)"),
            ("rigid_link", "Rigid link under large rotation"), ("rve", "Periodic RVE of a laminate"),
            ("contact", "Contact benchmarks")]
IMAGES = {"lame": [("lame_profiles.png", "σrr and σθθ through the wall against the exact solution")],
          "cantilever": [("cantilever_convergence.png", "tip-deflection error under refinement (CPS4 locks; CPS8 "
                          "reaches the 2D-vs-beam modelling difference)")],
          "rigid_link": [("rigid_link.png", "link force against P / sin θ over the 20 increments")],
          "contact": [("hertz_2k.png", "Hertz contact pressure (2k dofs) over the exact curve, tether and CalculiX"),
                      ("cattaneo_mindlin.png", "Cattaneo–Mindlin: tangential traction q(x) at Q = 0.5 μP over "
                       "Mindlin's curve (open markers stick, filled slip; dashed lines at ±c)"),
                      ("ironing_3mm.png", "ironing: Fx/|Fy| against the slide distance with the μ line and a ±2 % "
                       "band (top), Newton iterations of each increment (bottom)")]}


def write_markdown(path, results, meta):
    out = ["# Verification gallery", "",
           f"Generated by `{meta['command']}` on {meta['date']} (tether {meta['revision']}, "
           f"{meta['ccx_version']}; total {meta['total_wall']:.0f} s). Do not edit: rerun the command.", "",
           "Each row: the exact answer, tether's value and its relative error (tolerance: the bound the smoke "
           "test `tools.gallery` enforces), CalculiX's value and error where ccx can run the case, and wall time / "
           "Newton iterations (sum of ITRS in the `.sta`) of each code. Errors are relative to the exact value "
           "(patch tests: to the largest exact component). ccx expands 2D elements into one-layer 3D elements; "
           "see [compare_ccx.md](compare_ccx.md) for the modelling differences.", ""]
    for key, title in SECTIONS:
        out += [f"## {title}", ""]
        rows = results[key]
        out += ["| case | quantity | exact | tether | error | tol | ccx | ccx error | tether s / its | ccx s / its |",
                "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
        for r in rows:
            ccx_val = fmt(r["ccx"]) if r["ccx"] is not None else ("—" if r["ccx_error"] is not None else "")
            if r["ccx"] is None and r["ccx_error"] is None:
                ccx_val = meta["ccx_missing_note"] if (r["ccx_note"] is None and not meta["ccx"]) else "—"
            quantity = r["quantity"].replace("|", "\\|")
            out.append(f"| {r['case']} | {quantity} | {fmt(r['exact'])} | {fmt(r['tether'])} | "
                       f"{fmt_err(r['tether_error'])} | {r['tolerance']:.0e} | {ccx_val} | {fmt_err(r['ccx_error'])} | "
                       f"{fmt_run(r['tether_run'])} | {fmt_run(r['ccx_run'])} |")
        out += ["", "How each case was run:", ""]
        for r in rows:
            note = f" ccx: {r['ccx_note']}." if r["ccx_note"] else ""
            out.append(f"- **{r['case']}**, {r['quantity']}: {r['how']}.{note}")
        out.append("")
        for png, caption in IMAGES.get(key, []):
            out += [f"![{caption}](images/verification/{png})", "", f"*{caption}*", ""]
    with open(path, "w") as f:
        f.write("\n".join(out))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--tether", default=os.path.join(ROOT, "build", "bin", "tether"))
    ap.add_argument("--ccx", default="ccx")
    ap.add_argument("--out", default=os.path.join(ROOT, "docs"))
    ap.add_argument("--workdir", help="keep the runs here (default: a temporary folder, removed afterwards)")
    ap.add_argument("--json", help="also write the results as JSON")
    ap.add_argument("--quick", action="store_true",
                    help="no ccx runs of the long frictional cases (Cattaneo-Mindlin, ironing): the smoke test")
    args = ap.parse_args(argv)
    start = time.monotonic()
    tether = shutil.which(args.tether) or (args.tether if os.access(args.tether, os.X_OK) else None)
    if not tether:
        print(f"error: tether program '{args.tether}' not found (build target tether_cli)", file=sys.stderr)
        return 2
    tether = os.path.abspath(tether)
    if not shutil.which("gmsh"):
        print("error: gmsh not found (the Cattaneo-Mindlin and ironing deck generators mesh with it)", file=sys.stderr)
        return 2
    ccx = shutil.which(args.ccx)
    ccx = os.path.abspath(ccx) if ccx else None
    ccx_version = "ccx not found: ccx columns empty"
    if ccx:
        v = subprocess.run([ccx, "-v"], capture_output=True, text=True)
        ccx_version = "CalculiX " + (v.stdout.strip().split()[-1] if v.stdout.strip() else "?")
    images = os.path.join(args.out, "images", "verification")
    os.makedirs(images, exist_ok=True)
    work = args.workdir or tempfile.mkdtemp(prefix="tether_gallery_")
    os.makedirs(work, exist_ok=True)
    try:
        rn = Runner(tether, ccx, work)
        results = {"patch": bench_patch(rn), "lame": bench_lame(rn, images),
                   "cantilever": bench_cantilever(rn, images), "rigid_link": bench_rigid_link(rn, images),
                   "rve": bench_rve(rn), "contact": bench_contact(rn, images)}
        results["contact"] += bench_mindlin(rn, images, args.quick) + bench_ironing(rn, images, args.quick)
    finally:
        if not args.workdir:
            shutil.rmtree(work, ignore_errors=True)
    try:
        rev = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True, text=True)
        revision = rev.stdout.strip() or "?"
    except OSError:
        revision = "?"
    cmd = ("/usr/bin/python3 tools/make_gallery.py" + (" --ccx " + args.ccx if args.ccx != "ccx" else "")
           + (" --quick" if args.quick else ""))
    meta = {"command": cmd, "date": datetime.date.today().isoformat(),
            "revision": revision, "ccx_version": ccx_version, "ccx": bool(ccx),
            "ccx_missing_note": "ccx not installed", "quick": args.quick, "total_wall": time.monotonic() - start}
    write_markdown(os.path.join(args.out, "verification.md"), results, meta)
    failures = [f"{r['case']}: {r['quantity']}: error {r['tether_error']} beyond {r['tolerance']}"
                for rows in results.values() for r in rows
                if not (abs(r["tether_error"]) <= r["tolerance"])]
    if args.json:
        with open(args.json, "w") as f:
            json.dump({"meta": meta, "results": results, "failures": failures}, f, indent=2)
    for rows in results.values():
        for r in rows:
            print(f"{r['case']:34} {fmt_err(r['tether_error']):>10} (tol {r['tolerance']:.0e})  "
                  f"ccx {fmt_err(r['ccx_error']):>10}")
    print(f"wrote {os.path.join(args.out, 'verification.md')} and {images}/*.png in {meta['total_wall']:.1f} s")
    for f in failures:
        print("FAIL " + f, file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
