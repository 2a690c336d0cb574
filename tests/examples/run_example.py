#!/usr/bin/env python3
"""Runs one example deck with the tether program and checks its headline numbers.

Usage: run_example.py EXAMPLE TETHER_EXE SOURCE_DIR WORK_DIR USER_CONSTRAINT_MODULE

EXAMPLE is rigid_link, formula_constraint, user_constraint, periodic_rve, hertz, hertz_mortar,
plastic_cylinder (its deck written by the example's make_deck.py, read back by its plot_cylinder.py)
(the hertz deck run with its pair made TYPE=SURFACE TO SURFACE) or gmsh_lame (meshed
here by gmsh from its .geo; exit 77 when gmsh is missing). The deck is copied
into WORK_DIR (the user constraint's LIBRARY= is pointed at the module the build
made), run with `tether run -q`, and its .dat is read with tools/tethertools/dat.py.
The expected values are the exact ones quoted in the example's README.
Exit status 0 = OK, 1 = mismatch or failed run.
"""
import math
import os
import shutil
import subprocess
import sys

import tethertools.dat  # tools/ on PYTHONPATH (set by CTest)

TITLE = "constraint multipliers"


def fail(message):
    print("run_example.py:", message, file=sys.stderr)
    sys.exit(1)


def run(tether, deck, work):
    out = os.path.join(work, "out")
    shutil.rmtree(out, ignore_errors=True)
    result = subprocess.run([tether, "run", "-q", deck, "-o", out], capture_output=True, text=True, timeout=100)
    if result.returncode != 0:
        fail(f"tether exited with {result.returncode}: {result.stderr}")
    stem = os.path.splitext(os.path.basename(deck))[0]
    return tethertools.dat.read(os.path.join(out, stem + ".dat"))


def blocks_of(blocks, title, set_name):
    found = [b for b in blocks if b["title"].startswith(title) and b["set"] == set_name]
    if not found:
        fail(f"no '{title}' block for set {set_name}")
    return found


def driven_bead(blocks, x0, y0, load, set_name, constraint, exact_lambda):
    """Worst relative error of lambda over the increments, and the last lambda."""
    u = blocks_of(blocks, "displacements", set_name)
    m = blocks_of(blocks, TITLE, constraint)
    if len(u) != 20 or len(m) != 20:
        fail(f"{len(u)} displacement and {len(m)} multiplier blocks, expected 20 each")
    worst = 0.0
    for ub, mb in zip(u, m):
        x, y = x0 + ub["rows"][0][1], y0 + ub["rows"][0][2]
        lam = mb["rows"][0][3]
        worst = max(worst, abs(lam / exact_lambda(x, y, load) - 1))
    return worst, m[-1]["rows"][0][3]


def main(argv):
    if len(argv) != 6:
        print(__doc__, file=sys.stderr)
        return 2
    example, tether, source, work, module = argv[1:]
    os.makedirs(work, exist_ok=True)
    folder = os.path.join(source, "examples", example)

    if example == "rigid_link":
        blocks = run(tether, os.path.join(folder, "rigid_link.inp"), work)
        worst, last = driven_bead(blocks, 0.34729635533386083, -1.969615506024416, 3.0, "B", "LINK",
                                  lambda x, y, p: p / (-y / math.hypot(x, y)))
        exact = 3.0 / math.sin(math.radians(10))
        print(f"rigid_link: N at theta = 10 deg: {last:.6f} (exact P/sin(theta) = {exact:.6f}); "
              f"max relative error over 20 increments {worst:.1e}")
        if worst > 2e-6 or abs(last / exact - 1) > 2e-6:
            fail("link force differs from P / sin(theta)")
    elif example == "formula_constraint":
        blocks = run(tether, os.path.join(folder, "bead_on_ellipse.inp"), work)
        worst, last = driven_bead(blocks, 0.34729635533386083, -0.984807753012208, 3.0, "BEAD", "ELLIPSE",
                                  lambda x, y, p: p / (2 * abs(y)))
        exact = 3.0 / (2 * math.sin(math.radians(10)))
        print(f"formula_constraint: lambda at x = 2 cos 10deg: {last:.6f} (exact P/(2|y|) = {exact:.6f}); "
              f"max relative error over 20 increments {worst:.1e}")
        if worst > 2e-6 or abs(last / exact - 1) > 2e-6:
            fail("bead multiplier differs from P / (2|y|)")
        rf = blocks_of(blocks, "forces", "BEAD")[-1]["rows"][0][1]
        x = 2 * math.cos(math.radians(10))
        if abs(rf - last * x / 2) > 1e-5 * abs(rf):
            fail(f"horizontal reaction {rf} != lambda x / 2 = {last * x / 2}")
    elif example == "user_constraint":
        with open(os.path.join(folder, "equal_displacement.inp")) as f:
            text = f.read().replace("LIBRARY=build/libequal_displacement.so", "LIBRARY=" + module)
        deck = os.path.join(work, "equal_displacement.inp")
        with open(deck, "w") as f:
            f.write(text)
        blocks = run(tether, deck, work)
        u = {int(r[0]): r for r in blocks_of(blocks, "displacements", "NALL")[-1]["rows"]}
        lam = {s: blocks_of(blocks, TITLE, s)[-1]["rows"][0][3]
               for s in ("TIE-BOTTOM-X", "TIE-BOTTOM-Y", "TIE-TOP-X", "TIE-TOP-Y")}
        print(f"user_constraint: u_x(x=2) = {u[6][1]:.6f}, {u[7][1]:.6f} (exact 0.2), u_y(y=1) = {u[7][2]:.6f} "
              f"(exact -0.03), lambda = {lam}")
        if abs(u[6][1] - 0.2) > 1e-6 or abs(u[7][1] - 0.2) > 1e-6 or abs(u[7][2] + 0.03) > 1e-7:
            fail("displacements differ from the exact uniform-stress answer")
        if abs(lam["TIE-BOTTOM-X"] + 50) > 1e-4 or abs(lam["TIE-TOP-X"] + 50) > 1e-4:
            fail("x ties do not carry lambda = -50")
        if abs(lam["TIE-BOTTOM-Y"]) > 1e-6 or abs(lam["TIE-TOP-Y"]) > 1e-6:
            fail("y ties carry a force")
    elif example == "periodic_rve":
        blocks = run(tether, os.path.join(folder, "laminate_rve.inp"), work)
        forces = blocks_of(blocks, "forces", "REF")
        along = {int(r[0]): r for r in forces[0]["rows"]}[1001][1] / 1e-3
        across = {int(r[0]): r for r in forces[-1]["rows"]}[1002][2] / 1e-3
        print(f"periodic_rve: E along the layers {along:.4f} (rule of mixtures 437.5), "
              f"across {across:.4f} (inverse rule 150.9434)")
        if abs(along - 437.5) > 1e-3 or abs(across - 150.943396) > 1e-3:
            fail("effective moduli differ from the rules of mixtures")
    elif example == "hertz":
        blocks = run(tether, os.path.join(folder, "hertz.inp"), work)
        stress = [b for b in blocks if b["title"].startswith("contact stress")]
        if not stress:
            fail("no contact stress block")
        peak = max(r[1] for r in stress[-1]["rows"])
        p0 = 2644.96
        print(f"hertz: peak contact pressure {peak:.1f} MPa (exact p0 = {p0}), error {100 * (peak / p0 - 1):+.2f} %")
        if abs(peak / p0 - 1) > 0.01:
            fail("peak pressure more than 1 % from Hertz")
    elif example == "gmsh_lame":
        gmsh = shutil.which("gmsh")
        if not gmsh:
            print("gmsh_lame: gmsh is not installed (scripts/install-deps.sh installs it); skipped")
            return 77
        shutil.copy(os.path.join(folder, "lame_quarter.inp"), work)
        mesh = os.path.join(work, "lame_quarter_mesh.inp")
        subprocess.run([gmsh, "-2", "-format", "inp", os.path.join(folder, "lame_quarter.geo"), "-o", mesh],
                       check=True, capture_output=True, timeout=100)
        blocks = run(tether, os.path.join(work, "lame_quarter.inp"), work)
        # Lame, plane strain: u(r) = (1 + nu) a^2 p / (E (b^2 - a^2)) ((1 - 2 nu) r + b^2 / r), radial.
        a, b, p, e, nu = 10.0, 20.0, 100.0, 200000.0, 0.3
        exact = lambda r: (1 + nu) * a * a * p / (e * (b * b - a * a)) * ((1 - 2 * nu) * r + b * b / r)
        worst = 0.0
        for set_name, r in (("INNER", a), ("OUTER", b)):
            for row in blocks_of(blocks, "displacements", set_name)[-1]["rows"]:
                worst = max(worst, abs(math.hypot(row[1], row[2]) / exact(r) - 1))
        print(f"gmsh_lame: radial displacement at r = a, b within {worst:.1e} of Lame "
              f"(u(a) = {exact(a):.6e}, u(b) = {exact(b):.6e})")
        if worst > 1e-4:
            fail("radial displacement differs from Lame by more than 1e-4")
    elif example == "hertz_mortar":
        with open(os.path.join(folder, "hertz.inp")) as f:
            text = f.read().replace("TYPE=NODE TO SURFACE", "TYPE=SURFACE TO SURFACE", 1)
        os.makedirs(work, exist_ok=True)
        deck = os.path.join(work, "hertz_mortar.inp")
        with open(deck, "w") as f:
            f.write(text)
        blocks = run(tether, deck, work)
        stress = [b for b in blocks if b["title"].startswith("contact stress")]
        if not stress:
            fail("no contact stress block")
        peak = max(r[1] for r in stress[-1]["rows"])
        p0 = 2644.96
        print(f"hertz_mortar: peak contact pressure {peak:.1f} MPa (exact p0 = {p0}), error {100 * (peak / p0 - 1):+.2f} %")
        if abs(peak / p0 - 1) > 0.005:
            fail("mortar peak pressure more than 0.5 % from Hertz")
    elif example == "plastic_cylinder":
        deck = os.path.join(work, "cylinder.inp")
        with open(deck, "w") as f:
            subprocess.run([sys.executable, os.path.join(folder, "make_deck.py"), "24", "8"], stdout=f, check=True,
                           timeout=100)
        run(tether, deck, work)
        sys.path.insert(0, folder)
        import plot_cylinder  # the example's own reader and closed forms
        rows = plot_cylinder.history(os.path.join(work, "out", "cylinder.dat"), plot_cylinder.coordinates(deck))
        plot_cylinder.plot(rows, os.path.join(work, "out", "cylinder_1_20.vtu"), os.path.join(work, "cylinder.png"))
        loading = [r for r in rows if r[0] <= 1 + 1e-12]
        worst_below = max(abs(r[3] / plot_cylinder.hill_u_outer(r[1]) - 1) for r in loading if r[1] <= 152.0)
        at_190 = loading[-1][3] / plot_cylinder.hill_u_outer(loading[-1][1]) - 1
        print(f"plastic_cylinder: u(b) within {worst_below:.1e} of Hill up to 152 MPa, {100 * at_190:+.2f} % at 190 MPa; "
              f"yielding points {[r[4] for r in rows]}")
        if len(loading) != 20 or worst_below > 1e-3 or abs(at_190) > 0.03:
            fail("outer displacement differs from Hill's solution by more than 0.1 % (up to 152 MPa) or 3 % (190 MPa)")
        first_yield = plot_cylinder.hill_pressure(plot_cylinder.A)
        if any(r[4] for r in loading if r[1] < first_yield) or loading[-1][4] == 0:
            fail("AC YIELD: points yield below the first-yield pressure, or none at 190 MPa")
        if any(r[4] for r in rows if r[0] > 1 + 1e-12) or rows[-1][2] <= 0:
            fail("AC YIELD while unloading, or no residual bore displacement")
    else:
        fail(f"unknown example {example}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
