#!/usr/bin/python3
"""Writes a CalculiX/ABAQUS deck of the plane-strain Cattaneo-Mindlin problem (full model).

Model (units mm, N, MPa; plane strain, thickness 1):
  * Cylinder: a half disc of radius R = 10, centre (0, R), flat side up: the arc
    from (-R, R) through the contact point (0, 0) to (R, R), the flat face y = R.
    Element set CYL.
  * Block: the rectangle -L <= x <= L, -L <= y <= 0 (L = 20 R), top face y = 0
    touching the cylinder at the origin. Bottom (BOTTOM) fixed in x and y.
    Element set BLOCK. Both bodies E = 200000, nu = 0.3.
  * Loading plate: the flat top face of the cylinder moves rigidly in
    translation: *EQUATION u(n) - u(REF) = 0 (x and y) for every top node n,
    REF = the top node on x = 0. The equations carry no net force, only the
    couple that keeps the cylinder from rolling: a tangential load applied at
    the height R of the top face has a moment Q R about the contact (3000 N mm/mm
    for the default case) that the contact strip (width 2a ~ 1 mm) cannot carry.
    Loads are *CLOADs on REF.
  * Step 1 "NORMAL": the normal load P (default 2000 N/mm) on REF (-y) in
    --normal-increments equal increments, under pure load control (the cylinder
    touches at one point and is held vertically by contact alone). REF is held
    in x in this step only (by symmetry its reaction is zero: printed).
  * Step 2 "TANGENTIAL": *BOUNDARY, OP=NEW keeps only the supports; a tangential
    load Q = --ratio x mu P (default 0.5 x 0.3 x 2000 = 300 N/mm) on REF (+x) in
    --tangential-increments equal increments. The cylinder is now restrained in
    x by friction alone (exact stick: statically determined while Q < mu P).
  * Contact: slave = cylinder arc faces with |x| <= 2a (surface SLAVE), master =
    block top faces with |x| <= c (surface MASTER, the core), *SURFACE BEHAVIOR,
    PRESSURE-OVERCLOSURE=HARD (tether: exact, by multipliers; ccx: a penalty
    K = 50 E), *FRICTION mu (default 0.3; tether: exact stick by a multiplier)
    or, with --stick-slope K, "mu, K" (penalty stick in both codes; ccx has no
    exact stick: given mu alone it warns and uses a stick slope of 1e5; 1e7 =
    50 E was used for the comparison), *CONTACT PAIR, TYPE=NODE TO SURFACE.
  * Output, every increment of both steps: *NODE PRINT U of REF, RF totals of
    BOTTOM and REF (step 1), *CONTACT PRINT CSTR. --controls R_n C_n adds
    *CONTROLS, PARAMETERS=FIELD to both steps (ccx's defaults are loose).

Exact answers (identical materials: the normal and tangential problems
decouple, so this is the Hertz strip of a cylinder of radius R on an elastic
half-space of the same material, R* = R, E* = E / (2 (1 - nu^2)), tools/hertz_exact.py):
    a  = sqrt(4 P R / (pi E*)) = 0.4814 mm,  p0 = 2 P / (pi a) = 2645 MPa,
    stick zone |x| < c,  c = a sqrt(1 - Q / (mu P))           (0.3404 mm),
    q(x) = mu p0 (sqrt(1 - x^2/a^2) - (c/a) sqrt(1 - x^2/c^2))  for |x| < c,
    q(x) = mu p0 sqrt(1 - x^2/a^2)                             for c <= |x| <= a,
and the total tangential contact force is Q.

Mesh: the quarter meshes of tools/make_hertz_deck.py (gmsh 4.8 quads: a uniform
core of squares of size h, |x|, |y| <= c = --core x a (default 1.2 a), graded
outside) mirrored about x = 0, so the mesh is symmetric and has a node at the
contact point. The size grows by --growth (default 0.3) per unit of distance from the core (gmsh
meshes at 2h with growth 2 x --growth and splits every element into four).
--h sets h (default a / 40: 25.6k dofs), or --dofs a target count of
displacement dofs.
CPE8: mid-side nodes at edge midpoints (on the circle for arc edges).

Usage:
  make_mindlin_deck.py OUT.inp [--h H | --dofs N] [--element CPE4|CPE8] [--mu 0.3] [--ratio 0.5]
                       [--load 2000] [--normal-increments 10] [--tangential-increments 5]
                       [--stick-slope K] [--controls R_n C_n] [--core 1.2] [--growth 0.3] [--block 20]
                       [--gmsh gmsh] [--json OUT.json]
Prints one line with the mesh parameters and the exact a, c; --json writes them to a file.
"""
import argparse
import json
import math
import os
import sys
import tempfile

from tethertools import hertz_exact
from tethertools import make_hertz_deck as hz

R, E, NU = hertz_exact.R, hertz_exact.E, hertz_exact.NU
TOL = 1e-7 * R


def mindlin(P, Q, mu, R=R, E=E, nu=NU):
    """Exact plane-strain Hertz + Cattaneo-Mindlin figures (identical elastic bodies, R* = R)."""
    h = hertz_exact.hertz(P, R, E, nu, False)
    c = h["a"] * math.sqrt(1.0 - Q / (mu * P))
    return dict(h, Q=Q, mu=mu, c=c)


def traction(x, a, c, p0, mu):
    """Mindlin's tangential traction q(x) (same sign as Q)."""
    q = mu * p0 * math.sqrt(max(0.0, 1.0 - (x / a) ** 2))
    if abs(x) < c:
        q -= mu * p0 * (c / a) * math.sqrt(max(0.0, 1.0 - (x / c) ** 2))
    return q


def mirror(xy, quads):
    """Adds the mirror image about x = 0 (nodes on x = 0 shared); quads stay counter-clockwise."""
    xy = list(xy)
    image = {}
    for i, (x, y) in enumerate(list(xy)):
        if abs(x) <= TOL:
            image[i] = i
        else:
            image[i] = len(xy)
            xy.append((-x, y))
    out = [list(q) for q in quads]
    for q in quads:
        m = [image[n] for n in q]
        out.append([m[0], m[3], m[2], m[1]])
    return xy, out


def build(h, g, core, element, L, gmsh, workdir):
    mesh = hz.build_mesh(h, g, core, False, "CPE4", L, gmsh, workdir)
    xy, ncyl = mesh["xy"], mesh["ncyl"]
    cxy, cq = mirror(xy[:ncyl], mesh["cyl"])
    bxy, bq = mirror(xy[ncyl:], [[n - ncyl for n in e] for e in mesh["block"]])
    circle = hz.OnCircle(0.0, R, R)
    if element == "CPE8":
        cxy, cq = hz.add_midside(cxy, cq, circle)
        bxy, bq = hz.add_midside(bxy, bq, None)
    off = len(cxy)
    return {"xy": cxy + bxy, "cyl": cq, "block": [[n + off for n in e] for e in bq], "ncyl": off,
            "c": mesh["c"], "h": h, "g": g, "circle": circle}


def write_deck(path, mesh, opts, exact):
    xy, cyl, blk = mesh["xy"], mesh["cyl"], mesh["block"]
    a, core, h = exact["a"], mesh["c"], mesh["h"]
    circle = mesh["circle"]
    L = opts.block * R
    ncyl, ecyl = mesh["ncyl"], len(cyl)
    nid = lambda i: i + 1  # noqa: E731
    eid_blk = lambda k: ecyl + k + 1  # noqa: E731
    slave = hz.faces_where(cyl, xy, lambda x, y: circle(x, y) and abs(x) <= 2.0 * a + TOL)
    master = hz.faces_where(blk, xy, lambda x, y: abs(y) <= TOL and abs(x) <= core + TOL)
    top = hz.faces_where(cyl, xy, lambda x, y: abs(y - R) <= TOL)
    if not slave or not master or not top:
        raise RuntimeError("could not find the slave, master or top faces")
    slave_nodes = sorted({n for k, f in slave for n in hz.face_nodes(cyl[k], f)})
    master_nodes = sorted({n for k, f in master for n in hz.face_nodes(blk[k], f)})
    top_nodes = sorted({n for k, f in top for n in hz.face_nodes(cyl[k], f)})
    ref = [n for n in top_nodes if abs(xy[n][0]) <= TOL]
    if len(ref) != 1:
        raise RuntimeError("no top node on x = 0")
    ref = ref[0]
    block_nodes = list(range(ncyl, len(xy)))
    bottom = sorted(i for i in block_nodes if abs(xy[i][1] + L) <= TOL)
    dofs = 2 * len(xy)
    P, Q, mu = opts.load, exact["Q"], opts.mu
    heading = (f"Cattaneo-Mindlin plane strain full model: R={R:g} E={E:g} nu={NU:g} P={P:g} Q={Q:.12g} mu={mu:g} "
               f"element={opts.element} h={h:.6g} g={mesh['g']:.4g} core={core:.6g} dofs={dofs} "
               f"a={a:.6g} p0={exact['p0']:.6g} c={exact['c']:.6g}")
    out = ["*HEADING", heading, "** written by tools/make_mindlin_deck.py " + " ".join(sys.argv[1:]),
           "*NODE, NSET=NALL"]
    out += [f"{nid(i)}, {x:.12g}, {y:.12g}" for i, (x, y) in enumerate(xy)]

    def elements(name, elist, first):
        out.append(f"*ELEMENT, TYPE={opts.element}, ELSET={name}")
        out.extend(f"{first + k}, " + ", ".join(str(nid(n)) for n in e) for k, e in enumerate(elist))

    def nset(name, members):
        out.append(f"*NSET, NSET={name}")
        ids = [nid(n) for n in members]
        out.extend(", ".join(map(str, ids[k:k + 16])) for k in range(0, len(ids), 16))

    elements("CYL", cyl, 1)
    elements("BLOCK", blk, ecyl + 1)
    nset("NCYL", list(range(ncyl)))
    nset("NBLOCK", block_nodes)
    nset("BOTTOM", bottom)
    nset("TOPN", top_nodes)
    nset("REF", [ref])
    nset("SLAVEN", slave_nodes)
    nset("MASTERN", master_nodes)
    out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    out += [f"{k + 1}, S{f}" for k, f in slave]
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out += [f"{eid_blk(k)}, S{f}" for k, f in master]
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}",
            "*SOLID SECTION, ELSET=CYL, MATERIAL=STEEL", "1.",
            "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", "1.",
            "*SURFACE INTERACTION, NAME=SI",
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD",
            "*FRICTION", f"{mu:g}" + (f", {opts.stick_slope:g}" if opts.stick_slope else ""),
            "*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE", "SLAVE, MASTER"]
    out.append("** loading plate: the top face translates with REF (no rotation)")
    out.append("*EQUATION")
    for n in top_nodes:
        if n == ref:
            continue
        for d in (1, 2):
            out += ["2", f"{nid(n)}, {d}, 1., {nid(ref)}, {d}, -1."]
    out += ["*BOUNDARY", "BOTTOM, 1, 2"]
    output = ["*NODE PRINT, NSET=REF", "U",
              "*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY", "RF",
              "*CONTACT PRINT", "CSTR"]
    if opts.controls:
        output = ["*CONTROLS, PARAMETERS=FIELD", f"{opts.controls[0]:g}, {opts.controls[1]:g}"] + output
    n1, n2 = opts.normal_increments, opts.tangential_increments
    out += ["*STEP, NAME=NORMAL, INC=100", "*STATIC", f"{1.0 / n1:.12g}, 1., {1e-4 / n1:.12g}, {1.0 / n1:.12g}",
            "*BOUNDARY", "REF, 1, 1",
            "*CLOAD", f"REF, 2, {-P:.12g}",
            *output, "*NODE PRINT, NSET=REF, TOTALS=ONLY", "RF", "*END STEP"]
    out += ["*STEP, NAME=TANGENTIAL, INC=100", "*STATIC", f"{1.0 / n2:.12g}, 1., {1e-4 / n2:.12g}, {1.0 / n2:.12g}",
            "*BOUNDARY, OP=NEW", "BOTTOM, 1, 2",
            "*CLOAD", f"REF, 1, {Q:.12g}",
            *output, "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return {"deck": os.path.abspath(path), "element": opts.element, "h": h, "g": mesh["g"], "core": core,
            "nodes": len(xy), "elements": len(cyl) + len(blk), "dofs": dofs, "equations": 2 * (len(top_nodes) - 1),
            "slave_nodes": len(slave_nodes), "master_faces": len(master), "ref": nid(ref),
            "h_over_a": h / a, "a": a, "p0": exact["p0"], "c": exact["c"], "P": P, "Q": Q, "mu": mu,
            "R": R, "E": E, "nu": NU, "stick_slope": opts.stick_slope,
            "normal_increments": n1, "tangential_increments": n2}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("out")
    size = ap.add_mutually_exclusive_group()
    size.add_argument("--h", type=float, help="element size in the core [mm] (default a/40)")
    size.add_argument("--dofs", type=hz.parse_count, help="target number of displacement dofs instead of --h")
    ap.add_argument("--element", default="CPE4", type=str.upper, choices=["CPE4", "CPE8"])
    ap.add_argument("--mu", type=float, default=0.3, help="friction coefficient (default 0.3)")
    ap.add_argument("--ratio", type=float, default=0.5, help="Q / (mu P), < 1 (default 0.5)")
    ap.add_argument("--load", type=float, default=hertz_exact.P, help="normal line load P [N/mm] (default 2000)")
    ap.add_argument("--normal-increments", type=int, default=10, help="equal increments of step 1 (default 10)")
    ap.add_argument("--tangential-increments", type=int, default=5, help="equal increments of step 2 (default 5)")
    ap.add_argument("--stick-slope", type=float, default=0.0,
                    help="write '*FRICTION mu, K' (penalty stick, for ccx) instead of exact stick")
    ap.add_argument("--core", type=float, default=1.2, help="half-size of the uniform core in units of a (default 1.2)")
    ap.add_argument("--growth", type=float, default=0.3,
                    help="growth of the element size per unit distance from the core (default 0.3)")
    ap.add_argument("--block", type=float, default=20.0, help="block half-width and depth in units of R (default 20)")
    ap.add_argument("--controls", type=float, nargs=2, metavar=("R_n", "C_n"),
                    help="write *CONTROLS, PARAMETERS=FIELD with these in each step (both codes read it)")
    ap.add_argument("--gmsh", default="gmsh")
    ap.add_argument("--json", help="also write the mesh parameters and exact figures to this JSON file")
    opts = ap.parse_args(argv)
    if not 0 < opts.ratio < 1:
        ap.error("--ratio must be in (0, 1)")
    exact = mindlin(opts.load, opts.ratio * opts.mu * opts.load, opts.mu)
    a = exact["a"]
    with tempfile.TemporaryDirectory(prefix="mindlin_gmsh_") as work:
        def mesh_for(h):
            return build(h, opts.growth, opts.core * a, opts.element, opts.block * R, opts.gmsh, work)
        if opts.dofs:
            h = a / 40.0 * (math.sqrt(3.0) if opts.element == "CPE8" else 1.0)
            tried = []
            for _ in range(8):
                mesh = mesh_for(h)
                n = 2 * len(mesh["xy"])
                tried.append((abs(n / opts.dofs - 1.0), h, mesh))
                if abs(n / opts.dofs - 1.0) <= 0.05:
                    break
                h *= math.sqrt(n / opts.dofs) ** 1.1
            mesh = min(tried, key=lambda t: t[0])[2]
        else:
            mesh = mesh_for(opts.h or a / 40.0)
    info = write_deck(opts.out, mesh, opts, exact)
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump(info, f, indent=2)
    print(f"{opts.out}: {info['element']}  h = {info['h']:.4g} mm (a/{a / info['h']:.1f})  g = {info['g']:.3g}  "
          f"core {info['core']:.4g} mm  nodes {info['nodes']}  elements {info['elements']}  dofs {info['dofs']}  "
          f"slave nodes {info['slave_nodes']}  a = {a:.6g}  c = {exact['c']:.6g}  p0 = {exact['p0']:.6g}  "
          f"Q = {exact['Q']:.6g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
