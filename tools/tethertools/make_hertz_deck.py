#!/usr/bin/python3
"""Writes a CalculiX/ABAQUS deck of the plane-strain Hertz problem (symmetric half model).

Model (units mm, N, MPa; plane strain, thickness 1):
  * Cylinder: the half-cylinder's right half, a quarter disc of radius R = 10 with
    centre (0, R): the arc from the contact point (0, 0) to (R, R), the flat face
    y = R on top, the symmetry line x = 0. Element set CYL.
  * Elastic block (default): the rectangle 0 <= x <= L, -L <= y <= 0 (L = 20 R),
    top face y = 0 touching the cylinder at the origin (gap 0 there). Bottom fixed
    in y. Element set BLOCK.
  * --rigid-flat: the block is a one-row strip 0 <= x <= 2c, -h <= y <= 0 whose
    nodes are all fixed (*BOUNDARY NBLOCK, 1, 2): a rigid flat for node-to-surface
    contact with the cylinder as slave (tether has no rigid surfaces).
  * Symmetry: u_x = 0 on x = 0 (both bodies). Same material E = 200000, nu = 0.3.
  * Load: P/2 on the half model (P = 2000 N/mm for the whole cylinder by default) as
    a uniform pressure P/(2R) on the cylinder's flat top face (*DLOAD, P1..P4 per
    face); both codes apply it as a dead load without NLGEOM.
  * Contact: slave = cylinder arc faces with x <= 2a (surface SLAVE), master =
    block top faces with x <= c (surface MASTER); *SURFACE INTERACTION with
    *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD (tether: exact, by multipliers;
    ccx turns HARD into a linear penalty K = 50 E) or, with --linear K, LINEAR
    with slope K (a penalty in both codes); *CONTACT PAIR, TYPE=NODE TO SURFACE.
  * Output (last step): *NODE PRINT of U on SLAVEN, U and RF on MASTERN, RF totals
    on the supports, *CONTACT PRINT CSTR and (elastic block) *EL PRINT S of the
    block elements under the master faces (ELSET PRESSEL), from which
    tools/hertz_summary.py can recover the pressure when no CSTR block is printed.
    No field request (tether then writes ABAQUS's default, a .vtu per increment;
    ccx a .frd with the mesh only); --no-field-output adds *NODE FILE,
    FREQUENCY=0 so that neither writes field results (the speed benchmark).

Mesh: gmsh 4.8 (the `gmsh` program; the Python module is not needed), all quads.
Each body has a structured core of uniform squares of size h next to the contact
point (|x|, |y| <= c, c = --core * a, default 3 a, a = exact half-width of the
case) and an unstructured graded quad mesh outside it whose size grows as
h + g d with the distance d (max norm) from the core, capped at R/3 in the
cylinder and L/5 in the block. gmsh meshes at 2h / 2g with Blossom
recombination and splits every element (Mesh.SubdivisionAlgorithm = 1), which
gives an all-quad mesh. CPE8: mid-side nodes are added here at edge midpoints
(on the circle for arc edges). --dofs picks h, with g = min(gmax, 2 s / a),
s = node spacing (h for CPE4, h/2 for CPE8), gmax = 0.3 (CPE4) or 0.5 (CPE8), so
that the number of displacement dofs (2 x all nodes, the fixed rigid strip
included) is within 5 % of the target; --h sets h directly.

Pure load control (default) and the optional seating step. The undeformed
cylinder touches the block at one point (gap 0 at the origin), so under pure load
control its vertical rigid motion is held by nothing but contact. Measured with
ccx 2.20 and tether (docs/hertz_benchmark.md): both run this deck as it is, one
load-controlled step, ccx because its penalty contact element is generated and
stiff at zero clearance, tether because a node at zero gap starts closed. (The
note that ccx "floats" holds for a body that does not touch: with the cylinder
lifted by 0.01 mm ccx generates no contact element and stops with "too many
cutbacks", exit 201; lifted by 1e-6 or 1e-4 mm it still runs.)
For a code that needs it, --seat DELTA writes two steps:
  step 1 "seat": the top-face nodes (TOPN) are moved down by DELTA (e.g. 1e-4
         mm) under displacement control, which closes the contact at a few
         nodes with a small force (printed: RF total of TOPN, about 1 N at 2k);
  step 2 "load": *BOUNDARY, OP=NEW drops the seating condition (the supports are
         repeated) and the pressure is ramped to P/(2R).
The end state is the same load-controlled solution (ccx: the same pressures to
all printed digits with and without the seat). --no-seat (the default) writes
the single step. *CONTROLS (--controls R_n C_n) is read by both codes.
The generator needs only Python's standard library and the gmsh program.

Usage:
  make_hertz_deck.py OUT.inp [--dofs 25k | --h H] [--element CPE4|CPE8] [--rigid-flat]
                     [--load 2000] [--increments 10] [--seat DELTA | --no-seat]
                     [--linear K] [--controls R_n C_n] [--nlgeom] [--core 3] [--block 20]
                     [--gmsh gmsh] [--json OUT.json] [--plot MESH.png]
Prints one line with the mesh parameters; --json writes them (and a, p0) to a file;
--plot draws the mesh (needs matplotlib: /usr/bin/python3 on Debian).
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile

from tethertools import hertz_exact

R, E, NU = hertz_exact.R, hertz_exact.E, hertz_exact.NU
TOL = 1e-7 * R


def parse_count(text):
    """'25k' -> 25000, '1M' -> 1000000, '2300' -> 2300."""
    m = re.fullmatch(r"\s*([0-9.]+)\s*([kKmM]?)\s*", str(text))
    if not m:
        raise argparse.ArgumentTypeError(f"not a dof count: {text!r}")
    return int(round(float(m[1]) * {"": 1, "k": 1e3, "m": 1e6}[m[2].lower()]))


# ----------------------------------------------------------------------------- gmsh
GEO_OPTIONS = """
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
General.NumThreads = 1;
"""


def size_field(H, G, c, hmax):
    # gmsh element size at (x, y): H in the core |x|,|y| <= c, growing by G per unit of max-norm distance.
    return (f'Field[1] = MathEval;\nField[1].F = "min({hmax:.12g}, {H:.12g} + {G:.12g}*max(0, max(abs(x), abs(y)) - {c:.12g}))";\n'
            "Background Field = 1;\n")


def cylinder_geo(H, G, c, ng):
    """Quarter disc with a transfinite core next to the contact point (gmsh sizes: H, G; ng core segments)."""
    ya = R - math.sqrt(R * R - c * c)
    yb = c
    mg = max(1, round((yb - ya) / H))
    return (f"R = {R!r};\n"
            "Point(1) = {0, 0, 0};\nPoint(2) = {0, R, 0};\nPoint(3) = {R, R, 0};\n"
            f"Point(4) = {{{c!r}, {ya!r}, 0}};\nPoint(5) = {{{c!r}, {yb!r}, 0}};\nPoint(6) = {{0, {yb!r}, 0}};\n"
            "Circle(1) = {1, 2, 4};\nLine(2) = {4, 5};\nLine(3) = {5, 6};\nLine(4) = {6, 1};\n"
            "Circle(5) = {4, 2, 3};\nLine(6) = {3, 2};\nLine(7) = {2, 6};\n"
            f"Transfinite Curve{{1, 3}} = {ng + 1};\nTransfinite Curve{{2, 4}} = {mg + 1};\n"
            "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\nTransfinite Surface{1};\n"
            "Curve Loop(2) = {5, 6, 7, -3, -2};\nPlane Surface(2) = {2};\n"
            + size_field(H, G, c, 2 * R / 3) + GEO_OPTIONS)


def block_geo(H, G, c, ng, L):
    """Rectangle [0, L] x [-L, 0] with a transfinite square core [0, c] x [-c, 0]."""
    return (f"c = {c!r}; L = {L!r};\n"
            "Point(1) = {0, 0, 0};\nPoint(2) = {c, 0, 0};\nPoint(3) = {L, 0, 0};\nPoint(4) = {L, -L, 0};\n"
            "Point(5) = {0, -L, 0};\nPoint(6) = {0, -c, 0};\nPoint(7) = {c, -c, 0};\n"
            "Line(1) = {1, 2};\nLine(2) = {2, 7};\nLine(3) = {7, 6};\nLine(4) = {6, 1};\n"
            "Line(5) = {2, 3};\nLine(6) = {3, 4};\nLine(7) = {4, 5};\nLine(8) = {5, 6};\n"
            f"Transfinite Curve{{1, 2, 3, 4}} = {ng + 1};\n"
            "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\nTransfinite Surface{1};\n"
            "Curve Loop(2) = {5, 6, 7, 8, -3, -2};\nPlane Surface(2) = {2};\n"
            + size_field(H, G, c, 2 * L / 5) + GEO_OPTIONS)


def read_msh22(path):
    """Nodes {id: (x, y)} and quads [(n1..n4)] of an ASCII .msh 2.2 file (other 2D elements are an error)."""
    nodes, quads = {}, []
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if line.strip() == "$Nodes":
            for _ in range(int(next(lines))):
                t = next(lines).split()
                nodes[int(t[0])] = (float(t[1]), float(t[2]))
        elif line.strip() == "$Elements":
            for _ in range(int(next(lines))):
                t = [int(v) for v in next(lines).split()]
                etype, ntags = t[1], t[2]
                conn = t[3 + ntags:]
                if etype == 3:
                    quads.append(tuple(conn))
                elif etype in (2, 9, 10, 16):
                    raise RuntimeError(f"{path}: gmsh left a non-quad 2D element (type {etype})")
    return nodes, quads


def run_gmsh(geo_text, gmsh, workdir, name):
    geo = os.path.join(workdir, name + ".geo")
    msh = os.path.join(workdir, name + ".msh")
    with open(geo, "w") as f:
        f.write(geo_text)
    proc = subprocess.run([gmsh, geo, "-2", "-format", "msh22", "-o", msh, "-nt", "1"],
                          capture_output=True, text=True)
    if proc.returncode != 0 or not os.path.exists(msh):
        tail = "\n".join((proc.stdout + proc.stderr).splitlines()[-15:])
        raise RuntimeError(f"gmsh failed on {geo} (exit {proc.returncode}):\n{tail}")
    errors = [l for l in proc.stdout.splitlines() + proc.stderr.splitlines() if l.startswith("Error")]
    if errors:
        raise RuntimeError(f"gmsh reported errors on {geo}:\n" + "\n".join(errors[:10]))
    return read_msh22(msh)


def compact(nodes, quads):
    """Keeps only the nodes used by quads, numbered 0.. in first-use order; orients quads counter-clockwise."""
    index, xy, out = {}, [], []
    for q in quads:
        for n in q:
            if n not in index:
                index[n] = len(xy)
                xy.append(nodes[n])
        conn = [index[n] for n in q]
        area = 0.0
        for k in range(4):
            x1, y1 = xy[conn[k]]
            x2, y2 = xy[conn[(k + 1) % 4]]
            area += x1 * y2 - x2 * y1
        if area < 0:
            conn = [conn[0], conn[3], conn[2], conn[1]]
        out.append(conn)
    return xy, out


def strip_mesh(width, h):
    """One row of square-ish quads on [0, width] x [-h, 0] (the rigid flat), counter-clockwise."""
    n = max(1, round(width / h))
    xy = [(width * i / n, 0.0) for i in range(n + 1)] + [(width * i / n, -h) for i in range(n + 1)]
    quads = [[n + 1 + i, n + 2 + i, i + 1, i] for i in range(n)]
    return xy, quads


def add_midside(xy, quads, on_circle):
    """CPE8 connectivity: corners + mid-side nodes (edge k from corner k to k+1); arc edges get their node on the circle."""
    xy = list(xy)
    mids, out = {}, []
    for q in quads:
        conn = list(q)
        for k in range(4):
            a, b = q[k], q[(k + 1) % 4]
            key = (min(a, b), max(a, b))
            if key not in mids:
                (x1, y1), (x2, y2) = xy[a], xy[b]
                x, y = 0.5 * (x1 + x2), 0.5 * (y1 + y2)
                if on_circle is not None and on_circle(x1, y1) and on_circle(x2, y2):
                    cx, cy, r = on_circle.centre
                    d = math.hypot(x - cx, y - cy)
                    x, y = cx + (x - cx) * r / d, cy + (y - cy) * r / d
                mids[key] = len(xy)
                xy.append((x, y))
            conn.append(mids[key])
        out.append(conn)
    return xy, out


class OnCircle:
    def __init__(self, cx, cy, r):
        self.centre = (cx, cy, r)

    def __call__(self, x, y):
        cx, cy, r = self.centre
        return abs(math.hypot(x - cx, y - cy) - r) <= 1e-6 * r


# ----------------------------------------------------------------------------- model
def build_mesh(h, g, c, rigid, element, L, gmsh, workdir):
    """Meshes both bodies; returns dict with xy (0-based list), cyl/block element lists of 0-based node ids."""
    H, G = 2.0 * h, 2.0 * g
    ng = max(1, round(c / H))
    c_eff = ng * H  # the core edge holds an integer number of elements
    cyl_nodes, cyl_quads = run_gmsh(cylinder_geo(H, G, c_eff, ng), gmsh, workdir, "cylinder")
    cxy, cq = compact(cyl_nodes, cyl_quads)
    if rigid:
        bxy, bq = strip_mesh(2 * c_eff, h)
    else:
        blk_nodes, blk_quads = run_gmsh(block_geo(H, G, c_eff, ng, L), gmsh, workdir, "block")
        bxy, bq = compact(blk_nodes, blk_quads)
    circle = OnCircle(0.0, R, R)
    if element == "CPE8":
        cxy, cq = add_midside(cxy, cq, circle)
        bxy, bq = add_midside(bxy, bq, None)
    off = len(cxy)
    return {"xy": cxy + bxy, "cyl": cq, "block": [[n + off for n in e] for e in bq], "ncyl": off,
            "c": c_eff, "h": h, "g": g, "circle": circle}


def count_dofs(mesh):
    return 2 * len(mesh["xy"])


def faces_where(elements, xy, test):
    """(element index, face number 1..4) of quad faces whose two corners satisfy test(x, y)."""
    out = []
    for k, e in enumerate(elements):
        for f in range(4):
            a, b = e[f], e[(f + 1) % 4]
            if test(*xy[a]) and test(*xy[b]):
                out.append((k, f + 1))
    return out


def face_nodes(e, f):
    nodes = [e[f - 1], e[f % 4]]
    if len(e) == 8:
        nodes.append(e[3 + f])
    return nodes


def write_deck(path, mesh, opts, exact):
    xy, cyl, blk = mesh["xy"], mesh["cyl"], mesh["block"]
    etype = opts.element
    a, c, h = exact["a"], mesh["c"], mesh["h"]
    x_slave, x_master = 2.0 * a, c
    L = opts.block * R
    circle = mesh["circle"]
    nid = lambda i: i + 1  # noqa: E731
    ncyl = mesh["ncyl"]
    ecyl = len(cyl)
    eid_blk = lambda k: ecyl + k + 1  # noqa: E731

    slave = faces_where(cyl, xy, lambda x, y: circle(x, y) and x <= x_slave + TOL)
    top = faces_where(cyl, xy, lambda x, y: abs(y - R) <= TOL)
    master = faces_where(blk, xy, lambda x, y: abs(y) <= TOL and x <= x_master + TOL)
    if not slave or not top or not master:
        raise RuntimeError("could not find the slave, load or master faces")
    slave_nodes = sorted({n for k, f in slave for n in face_nodes(cyl[k], f)})
    master_nodes = sorted({n for k, f in master for n in face_nodes(blk[k], f)})
    top_nodes = sorted({n for k, f in top for n in face_nodes(cyl[k], f)})
    symm = sorted(i for i, (x, y) in enumerate(xy) if abs(x) <= TOL)
    block_nodes = list(range(ncyl, len(xy)))
    bottom = sorted(i for i in block_nodes if abs(xy[i][1] + L) <= TOL)
    cyl_nodes = list(range(ncyl))
    dofs = 2 * len(xy)
    fixed = {(n, 0) for n in symm} | ({(n, d) for n in block_nodes for d in (0, 1)} if opts.rigid_flat
                                     else {(n, 1) for n in bottom})
    pressure = opts.load / (2.0 * R)
    heading = (f"Hertz plane strain half model: R={R:g} E={E:g} nu={NU:g} P={opts.load:g} "
               f"rigid_flat={int(opts.rigid_flat)} element={etype} h={h:.6g} g={mesh['g']:.4g} c={c:.6g} "
               f"dofs={dofs} a={a:.6g} p0={exact['p0']:.6g}")
    out = ["*HEADING", heading,
           "** written by tools/make_hertz_deck.py " + " ".join(sys.argv[1:])]
    out.append("*NODE, NSET=NALL")
    out += [f"{nid(i)}, {x:.12g}, {y:.12g}" for i, (x, y) in enumerate(xy)]

    def elements(name, elist, first):
        out.append(f"*ELEMENT, TYPE={etype}, ELSET={name}")
        out.extend(f"{first + k}, " + ", ".join(str(nid(n)) for n in e) for k, e in enumerate(elist))

    elements("CYL", cyl, 1)
    elements("BLOCK", blk, ecyl + 1)

    def nset(name, members):
        out.append(f"*NSET, NSET={name}")
        ids = [nid(n) for n in members]
        out.extend(", ".join(map(str, ids[k:k + 16])) for k in range(0, len(ids), 16))

    def elset(name, members):
        out.append(f"*ELSET, ELSET={name}")
        out.extend(", ".join(map(str, members[k:k + 16])) for k in range(0, len(members), 16))

    nset("NCYL", cyl_nodes)
    nset("NBLOCK", block_nodes)
    nset("SYMM", symm)
    if not opts.rigid_flat:
        nset("BOTTOM", bottom)
    nset("TOPN", top_nodes)
    nset("SLAVEN", slave_nodes)
    nset("MASTERN", master_nodes)
    load_sets = {}
    for k, f in top:
        load_sets.setdefault(f, []).append(k + 1)
    for f, members in sorted(load_sets.items()):
        elset(f"LOAD_S{f}", members)
    if not opts.rigid_flat:
        # the block elements under the contact: their stresses give the pressure when no CSTR is printed
        elset("PRESSEL", sorted({eid_blk(k) for k, f in master}))
    out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    out += [f"{k + 1}, S{f}" for k, f in slave]
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out += [f"{eid_blk(k)}, S{f}" for k, f in master]
    out += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E:g}, {NU:g}",
            "*SOLID SECTION, ELSET=CYL, MATERIAL=STEEL", "1.",
            "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", "1.",
            "*SURFACE INTERACTION, NAME=SI"]
    if opts.linear:
        out += ["*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{opts.linear:g}"]
    else:
        out += ["*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD"]
    out += ["*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE", "SLAVE, MASTER"]
    supports = ["SYMM, 1, 1"] + (["NBLOCK, 1, 2"] if opts.rigid_flat else ["BOTTOM, 2, 2"])
    out += ["*BOUNDARY"] + supports
    nl = ", NLGEOM" if opts.nlgeom else ""
    controls = []
    if opts.controls:
        controls = ["*CONTROLS, PARAMETERS=FIELD", f"{opts.controls[0]:g}, {opts.controls[1]:g}"]
    if opts.seat:
        out += [f"*STEP{nl}, INC=100", "*STATIC", "1., 1.", *controls,
                "*BOUNDARY", f"TOPN, 2, 2, {-opts.seat:g}",
                "*NODE PRINT, NSET=TOPN, TOTALS=ONLY", "RF", "*END STEP"]
    dt = 1.0 / opts.increments
    out += [f"*STEP{nl}, INC={max(100, 10 * opts.increments)}", "*STATIC", f"{dt:.6g}, 1., {1e-4 * dt:.6g}, {dt:.6g}"]
    if opts.seat:
        out += ["*BOUNDARY, OP=NEW"] + supports
    else:
        out += controls
    if opts.seat:
        out += controls
    out.append("*DLOAD")
    out += [f"LOAD_S{f}, P{f}, {pressure:.12g}" for f in sorted(load_sets)]
    out += ["*NODE PRINT, NSET=SLAVEN", "U",
            "*NODE PRINT, NSET=MASTERN", "U, RF",
            f"*NODE PRINT, NSET={'NBLOCK' if opts.rigid_flat else 'BOTTOM'}, TOTALS=ONLY", "RF",
            "*CONTACT PRINT", "CSTR"]
    if not opts.rigid_flat:
        out += ["*EL PRINT, ELSET=PRESSEL", "S"]
    if opts.no_field_output:
        # A field request that writes nothing: tether then writes no .vtu (no
        # default output), ccx no results in its .frd (it writes none for
        # this deck anyway): the same output request in both codes.
        out += ["*NODE FILE, FREQUENCY=0", "U"]
    out.append("*END STEP")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return {"deck": os.path.abspath(path), "element": etype, "rigid_flat": bool(opts.rigid_flat),
            "h": h, "g": mesh["g"], "core": c, "block_size": None if opts.rigid_flat else L,
            "nodes": len(xy), "elements": len(cyl) + len(blk), "dofs": dofs,
            "cylinder_nodes": ncyl, "block_nodes": len(block_nodes),
            "free_dofs": 2 * len(xy) - len(fixed),
            "slave_faces": len(slave), "slave_nodes": len(slave_nodes), "slave_x_max": x_slave,
            "master_faces": len(master), "master_x_max": x_master,
            "h_over_a": h / a, "a": a, "p0": exact["p0"], "Estar": exact["Estar"], "P": opts.load,
            "R": R, "E": E, "nu": NU, "pressure": pressure, "seat": opts.seat, "increments": opts.increments,
            "behavior": f"LINEAR {opts.linear:g}" if opts.linear else "HARD"}


def plot_mesh(mesh, path, a):
    """Three views of the mesh (whole model, cylinder, contact zone) into a PNG (needs matplotlib)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    xy = mesh["xy"]
    polys = [[xy[n] for n in e[:4]] for e in mesh["cyl"] + mesh["block"]]
    c = mesh["c"]
    ymin = min(y for _, y in xy)
    views = [("model", (-0.02 * R, max(x for x, _ in xy), ymin, 1.05 * R)),
             ("cylinder and the block near it", (-0.02 * R, 1.2 * R, -0.6 * R, 1.05 * R)),
             (f"contact zone (a = {a:.3g} mm)", (-0.05 * c, 1.3 * c, -0.7 * c, 0.9 * c))]
    fig, axes = plt.subplots(1, 3, figsize=(15, 5))
    for ax, (title, (x0, x1, y0, y1)) in zip(axes, views):
        ax.add_collection(PolyCollection(polys, facecolors="none", edgecolors="k", linewidths=0.25))
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=10)
    axes[2].axvline(a, color="tab:red", lw=0.8, ls="--")
    fig.tight_layout()
    fig.savefig(path, dpi=80)
    plt.close(fig)


def growth_for(h, a, element):
    """Size growth per unit distance outside the core: 2 (node spacing)/a, at most 0.3 (CPE4) or 0.5 (CPE8)."""
    spacing = h / 2.0 if element == "CPE8" else h
    return min(0.5 if element == "CPE8" else 0.3, 2.0 * spacing / a)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("out")
    size = ap.add_mutually_exclusive_group()
    size.add_argument("--dofs", type=parse_count, help="target number of displacement dofs: 2k, 25k, 230k, 1M, ...")
    size.add_argument("--h", type=float, help="element size at the contact [mm] (instead of --dofs)")
    ap.add_argument("--element", default="CPE4", type=str.upper, choices=["CPE4", "CPE8"])
    ap.add_argument("--rigid-flat", action="store_true", help="a fixed strip (rigid flat) instead of the elastic block")
    ap.add_argument("--load", type=float, default=hertz_exact.P, help="line load P of the whole cylinder [N/mm] (default 2000)")
    ap.add_argument("--increments", type=int, default=10, help="equal load increments in the load step (default 10)")
    seat = ap.add_mutually_exclusive_group()
    seat.add_argument("--seat", type=float, default=0.0, metavar="DELTA",
                      help="first a seating step moving the top face down by DELTA [mm] (e.g. 1e-4)")
    seat.add_argument("--no-seat", dest="seat", action="store_const", const=0.0,
                      help="one load-controlled step (the default)")
    ap.add_argument("--linear", type=float, metavar="K", help="PRESSURE-OVERCLOSURE=LINEAR with slope K [MPa/mm] instead of HARD")
    ap.add_argument("--controls", type=float, nargs=2, metavar=("R_n", "C_n"), help="write *CONTROLS, PARAMETERS=FIELD with these")
    ap.add_argument("--nlgeom", action="store_true", help="NLGEOM steps (Hertz theory is small-strain: off by default)")
    ap.add_argument("--core", type=float, default=3.0, help="half-size of the uniform core in units of a (default 3)")
    ap.add_argument("--block", type=float, default=20.0, help="block half-width and depth in units of R (default 20)")
    ap.add_argument("--gmsh", default="gmsh", help="gmsh program (default gmsh)")
    ap.add_argument("--no-field-output", action="store_true",
                    help="ask for no field output (*NODE FILE, FREQUENCY=0): no .vtu from tether, no results in ccx's .frd")
    ap.add_argument("--json", help="also write the mesh parameters to this JSON file")
    ap.add_argument("--plot", metavar="PNG", help="also draw the mesh (whole, cylinder, contact zone) into this PNG (matplotlib)")
    opts = ap.parse_args(argv)
    exact = hertz_exact.hertz(opts.load, R, E, NU, opts.rigid_flat)
    a = exact["a"]
    c = opts.core * a
    with tempfile.TemporaryDirectory(prefix="hertz_gmsh_") as work:
        if opts.h:
            mesh = build_mesh(opts.h, growth_for(opts.h, a, opts.element), c, opts.rigid_flat, opts.element, opts.block * R, opts.gmsh, work)
        else:
            target = opts.dofs or 25000
            # dofs ~ h^-2: start from a guess, correct by the measured count (a few gmsh runs).
            h = a / 20.0 * math.sqrt(25000.0 / target) * (math.sqrt(3.0) if opts.element == "CPE8" else 1.0)
            tried = []
            for _ in range(8):
                mesh = build_mesh(h, growth_for(h, a, opts.element), c, opts.rigid_flat, opts.element, opts.block * R, opts.gmsh, work)
                n = count_dofs(mesh)
                tried.append((abs(n / target - 1.0), h, mesh))
                if abs(n / target - 1.0) <= 0.05:
                    break
                h *= math.sqrt(n / target) ** 1.1
            mesh = min(tried, key=lambda t: t[0])[2]
    info = write_deck(opts.out, mesh, opts, exact)
    if opts.plot:
        plot_mesh(mesh, opts.plot, a)
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump(info, f, indent=2)
    print(f"{opts.out}: {info['element']} {'rigid flat' if info['rigid_flat'] else 'elastic block'}  "
          f"h = {info['h']:.4g} mm (a/{a / info['h']:.1f})  g = {info['g']:.3g}  core {info['core']:.4g} mm  "
          f"nodes {info['nodes']}  elements {info['elements']}  dofs {info['dofs']}  "
          f"slave nodes {info['slave_nodes']}  a = {a:.6g}  p0 = {exact['p0']:.6g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
