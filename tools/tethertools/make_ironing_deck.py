#!/usr/bin/python3
"""Writes a CalculiX/ABAQUS deck of the plane-strain ironing problem (a die pressed into a block and slid along it).

Model (units mm, N, MPa; plane strain, thickness 1; NLGEOM in both steps):
  * Die: a half disc of radius Rd (--radius, default 5), flat side up, centre
    (X0, Rd), so that its lowest point (X0, 0) touches the block; X0 = --margin
    (default 10). Element set DIE, E = --die-modulus x E (default 1: the same
    material as the block), nu = 0.3. The nodes of its flat top (TOPN) are
    driven.
  * Block: the rectangle 0 <= x <= X0 + S + margin, -H <= y <= 0 (H = --depth,
    default 10). Bottom (BOTTOM) fixed in x and y. Element set BLOCK,
    E = 200000, nu = 0.3.
  * Step 1 "INDENT": TOPN moved down by --indent (default 0.02 mm) in
    --indent-increments equal increments, u_x = 0: a shallow indentation (contact
    half-width a of a few percent of Rd), so that the contact normals stay
    within a few degrees of vertical.
  * Step 2 "SLIDE": TOPN moved by S = --slide (default 3 Rd = 15 mm) in +x in
    --slide-increments (default 120) equal increments, the indentation held:
    the die slides over S / h = 150 master segments (h = --master-size), 1.25
    per increment; every slave node crosses all of them.
  * Contact: slave = die arc faces with |x - X0| <= --slave-width (default 1 mm),
    surface SLAVE; master = block top faces over the track X0 - 2 <= x <= X0 + S + 2
    (surface MASTER, uniform segments of length h); PRESSURE-OVERCLOSURE=HARD
    (tether: exact; ccx: penalty K = 50 E), *FRICTION mu (--mu, default 0.3;
    exact stick in tether) or "mu, K" with --stick-slope K (penalty stick, for
    ccx, which otherwise defaults to 1e5); --mu 0 writes no *FRICTION;
    *CONTACT PAIR, TYPE=NODE TO SURFACE. --die-as-master swaps the roles (the
    surface names stay): the track's nodes become the slaves of the die's arc.
  * Output, every increment: *NODE PRINT, NSET=TOPN, TOTALS=ONLY of RF (the
    force the drivers exert on the die: Fx, Fy), U of REF (the top node above
    the die centre), *CONTACT PRINT CSTR. --controls R_n C_n adds *CONTROLS,
    PARAMETERS=FIELD to both steps.

What to expect. In steady sliding every contact node slips, so the friction
force is mu times the normal force; the horizontal driving force is
    Fx = mu N + (horizontal part of the normal contact force),
and the second term (ploughing) vanishes when the pressure is symmetric about
the die axis: exactly so for identical elastic materials in the small-strain
theory (the normal and tangential problems decouple; Dundurs' beta = 0), to
O(a / Rd) otherwise. So Fx / |Fy| = mu (within a few 0.1 %) and, with mu = 0,
Fx = 0 up to the discretisation noise of the faceted master surface.

Mesh: gmsh 4.8 (the `gmsh` program), all quads: meshed at twice the target
size with Blossom recombination, every element split into four
(Mesh.SubdivisionAlgorithm = 1). The block's top edge along the track is
divided uniformly into segments of length h (--master-size, default 0.1),
and the layer under it down to --track-depth (default 0.5 mm) has that size;
elsewhere the size grows by --growth (default 0.3) per unit distance from the
track, capped at H/5. The die's size is --slave-size (default 0.05) within
--slave-width of its lowest point, growing by --growth per unit distance
beyond, capped at Rd/5. CPE8
(--element): mid-side nodes at edge midpoints (on the circle for the die's arc
edges); --master-element sets the block's type separately.

Usage:
  make_ironing_deck.py OUT.inp [--mu 0.3] [--stick-slope K] [--element CPE4|CPE8] [--master-element ...]
                       [--radius 5] [--indent 0.02] [--slide 15] [--indent-increments 4]
                       [--slide-increments 120] [--master-size 0.1] [--slave-size 0.05]
                       [--slave-width 1] [--die-modulus 1] [--margin 10] [--depth 10] [--track-depth 0.5]
                       [--controls R_n C_n]
                       [--growth 0.3]
                       [--gmsh gmsh] [--json OUT.json]
Prints one line with the mesh parameters; --json writes them to a file.
"""
import argparse
import json
import os
import sys
import tempfile

from tethertools import make_hertz_deck as hz

E, NU = 200000.0, 0.3
TOL = 1e-7


def die_geo(Rd, x0, H, G, hmax, core):
    """Half disc, centre (x0, Rd), flat side up; size H within `core` of the lowest point, growing by G beyond."""
    return (f"Rd = {Rd!r}; x0 = {x0!r};\n"
            "Point(1) = {x0, Rd, 0};\nPoint(2) = {x0 - Rd, Rd, 0};\nPoint(3) = {x0, 0, 0};\n"
            "Point(4) = {x0 + Rd, Rd, 0};\n"
            "Circle(1) = {2, 1, 3};\nCircle(2) = {3, 1, 4};\nLine(3) = {4, 1};\nLine(4) = {1, 2};\n"
            "Curve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
            f'Field[1] = MathEval;\nField[1].F = "min({hmax!r}, {H!r} + {G!r}*max(0, sqrt((x - {x0!r})^2 + y^2) - {core!r}))";\n'
            "Background Field = 1;\n" + hz.GEO_OPTIONS)


def block_geo(L, D, t0, t1, H, G, hmax, depth):
    """Rectangle [0, L] x [-D, 0]; the top edge over [t0, t1] divided uniformly into segments of size H,
    size H in the layer [t0, t1] x [-depth, 0], growing by G with the distance from it."""
    n = max(1, round((t1 - t0) / H))
    return (f"L = {L!r}; D = {D!r}; t0 = {t0!r}; t1 = {t1!r};\n"
            "Point(1) = {0, 0, 0};\nPoint(2) = {t0, 0, 0};\nPoint(3) = {t1, 0, 0};\nPoint(4) = {L, 0, 0};\n"
            "Point(5) = {L, -D, 0};\nPoint(6) = {0, -D, 0};\n"
            "Line(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\nLine(4) = {4, 5};\nLine(5) = {5, 6};\n"
            "Line(6) = {6, 1};\n"
            f"Transfinite Curve{{2}} = {n + 1};\n"
            "Curve Loop(1) = {1, 2, 3, 4, 5, 6};\nPlane Surface(1) = {1};\n"
            f'Field[1] = MathEval;\nField[1].F = "min({hmax!r}, {H!r} + {G!r}*sqrt(max(0, max({t0!r} - x, x - {t1!r}))^2 + max(0, -y - {depth!r})^2))";\n'
            "Background Field = 1;\n" + hz.GEO_OPTIONS)


def build_mesh(opts, workdir):
    Rd, x0 = opts.radius, opts.margin
    t0, t1 = x0 - 2.0, x0 + opts.slide + 2.0
    L = x0 + opts.slide + opts.margin
    dn, dq = hz.run_gmsh(die_geo(Rd, x0, 2 * opts.slave_size, 2 * opts.growth, Rd / 2.5,
                                       opts.slave_width), opts.gmsh, workdir, "die")
    dxy, dq = hz.compact(dn, dq)
    bn, bq = hz.run_gmsh(block_geo(L, opts.depth, t0, t1, 2 * opts.master_size, 2 * opts.growth, opts.depth / 2.5,
                                   opts.track_depth),
                         opts.gmsh, workdir, "block")
    bxy, bq = hz.compact(bn, bq)
    circle = hz.OnCircle(x0, Rd, Rd)
    if opts.element == "CPE8":
        dxy, dq = hz.add_midside(dxy, dq, circle)
    if opts.master_element == "CPE8":
        bxy, bq = hz.add_midside(bxy, bq, None)
    off = len(dxy)
    return {"xy": dxy + bxy, "die": dq, "block": [[n + off for n in e] for e in bq], "ndie": off,
            "circle": circle, "track": (t0, t1), "L": L}


def write_deck(path, mesh, opts):
    xy, die, blk = mesh["xy"], mesh["die"], mesh["block"]
    Rd, x0 = opts.radius, opts.margin
    circle = mesh["circle"]
    t0, t1 = mesh["track"]
    ndie, edie = mesh["ndie"], len(die)
    nid = lambda i: i + 1  # noqa: E731
    eid_blk = lambda k: edie + k + 1  # noqa: E731
    slave = hz.faces_where(die, xy, lambda x, y: circle(x, y) and abs(x - x0) <= opts.slave_width + TOL)
    master = hz.faces_where(blk, xy, lambda x, y: abs(y) <= TOL and t0 - TOL <= x <= t1 + TOL)
    top = hz.faces_where(die, xy, lambda x, y: abs(y - Rd) <= TOL)
    if not slave or not master or not top:
        raise RuntimeError("could not find the slave, master or top faces")
    slave_nodes = sorted({n for k, f in slave for n in hz.face_nodes(die[k], f)})
    top_nodes = sorted({n for k, f in top for n in hz.face_nodes(die[k], f)})
    ref = min(top_nodes, key=lambda n: abs(xy[n][0] - x0))
    block_nodes = list(range(ndie, len(xy)))
    bottom = sorted(i for i in block_nodes if abs(xy[i][1] + opts.depth) <= TOL)
    seg = sorted(abs(xy[hz.face_nodes(blk[k], f)[1]][0] - xy[hz.face_nodes(blk[k], f)[0]][0]) for k, f in master)
    dofs = 2 * len(xy)
    etype_die, etype_blk = opts.element, opts.master_element
    heading = (f"Ironing plane strain: Rd={Rd:g} X0={x0:g} E={E:g} Edie={opts.die_modulus * E:g} nu={NU:g} "
               f"mu={opts.mu:g} indent={opts.indent:g} slide={opts.slide:g} die={etype_die} block={etype_blk} "
               f"master_size={opts.master_size:g} slave_size={opts.slave_size:g} dofs={dofs}")
    out = ["*HEADING", heading, "** written by tools/make_ironing_deck.py " + " ".join(sys.argv[1:]),
           "*NODE, NSET=NALL"]
    out += [f"{nid(i)}, {x:.12g}, {y:.12g}" for i, (x, y) in enumerate(xy)]

    def elements(name, etype, elist, first):
        out.append(f"*ELEMENT, TYPE={etype}, ELSET={name}")
        out.extend(f"{first + k}, " + ", ".join(str(nid(n)) for n in e) for k, e in enumerate(elist))

    def nset(name, members):
        out.append(f"*NSET, NSET={name}")
        ids = [nid(n) for n in members]
        out.extend(", ".join(map(str, ids[k:k + 16])) for k in range(0, len(ids), 16))

    elements("DIE", etype_die, die, 1)
    elements("BLOCK", etype_blk, blk, edie + 1)
    nset("NDIE", list(range(ndie)))
    nset("NBLOCK", block_nodes)
    nset("BOTTOM", bottom)
    nset("TOPN", top_nodes)
    nset("REF", [ref])
    nset("SLAVEN", slave_nodes)
    out.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    out += [f"{k + 1}, S{f}" for k, f in slave]
    out.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    out += [f"{eid_blk(k)}, S{f}" for k, f in master]
    out += ["*MATERIAL, NAME=DIE", "*ELASTIC", f"{opts.die_modulus * E:g}, {NU:g}",
            "*MATERIAL, NAME=BLOCK", "*ELASTIC", f"{E:g}, {NU:g}",
            "*SOLID SECTION, ELSET=DIE, MATERIAL=DIE", "1.",
            "*SOLID SECTION, ELSET=BLOCK, MATERIAL=BLOCK", "1.",
            "*SURFACE INTERACTION, NAME=SI",
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD"]
    if opts.mu > 0:
        out += ["*FRICTION", f"{opts.mu:g}" + (f", {opts.stick_slope:g}" if opts.stick_slope else "")]
    # --die-as-master swaps the roles, not the surface names: the die's arc
    # (surface SLAVE) becomes the master and the block's track (surface
    # MASTER) the slave, as ABAQUS advises for a die much stiffer than the block.
    out += ["*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE",
            "MASTER, SLAVE" if opts.die_as_master else "SLAVE, MASTER",
            "*BOUNDARY", "BOTTOM, 1, 2"]
    output = ["*NODE PRINT, NSET=TOPN, TOTALS=ONLY", "RF", "*NODE PRINT, NSET=REF", "U",
              "*CONTACT PRINT", "CSTR"]
    if opts.controls:
        output = ["*CONTROLS, PARAMETERS=FIELD", f"{opts.controls[0]:g}, {opts.controls[1]:g}"] + output
    n1, n2 = opts.indent_increments, opts.slide_increments
    out += ["*STEP, NAME=INDENT, NLGEOM, INC=100", "*STATIC", f"{1.0 / n1:.12g}, 1., {1e-4 / n1:.12g}, {1.0 / n1:.12g}",
            "*BOUNDARY", "TOPN, 1, 1", f"TOPN, 2, 2, {-opts.indent:.12g}", *output, "*END STEP"]
    out += [f"*STEP, NAME=SLIDE, NLGEOM, INC={max(100, 4 * n2)}", "*STATIC",
            f"{1.0 / n2:.12g}, 1., {1e-4 / n2:.12g}, {1.0 / n2:.12g}",
            "*BOUNDARY", f"TOPN, 1, 1, {opts.slide:.12g}", f"TOPN, 2, 2, {-opts.indent:.12g}", *output, "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    return {"deck": os.path.abspath(path), "die_element": etype_die, "block_element": etype_blk,
            "nodes": len(xy), "elements": len(die) + len(blk), "dofs": dofs,
            "slave_nodes": len(slave_nodes), "master_faces": len(master),
            "master_segment": [seg[0], seg[-1]], "track": [t0, t1], "block_length": mesh["L"],
            "top_nodes": len(top_nodes), "ref": nid(ref), "radius": Rd, "x0": x0, "mu": opts.mu,
            "indent": opts.indent, "slide": opts.slide, "E": E, "die_E": opts.die_modulus * E, "nu": NU,
            "stick_slope": opts.stick_slope, "die_as_master": opts.die_as_master,
            "indent_increments": n1, "slide_increments": n2,
            "segments_per_increment": opts.slide / n2 / opts.master_size}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    ap.add_argument("out")
    ap.add_argument("--mu", type=float, default=0.3, help="friction coefficient (default 0.3; 0: frictionless)")
    ap.add_argument("--stick-slope", type=float, default=0.0, help="write '*FRICTION mu, K' (penalty stick, for ccx)")
    ap.add_argument("--element", default="CPE4", type=str.upper, choices=["CPE4", "CPE8"], help="die (slave) elements")
    ap.add_argument("--master-element", type=str.upper, choices=["CPE4", "CPE8"],
                    help="block (master) elements (default: --element)")
    ap.add_argument("--radius", type=float, default=5.0, help="die radius Rd [mm] (default 5)")
    ap.add_argument("--indent", type=float, default=0.02, help="downward displacement of the die top [mm] (default 0.02)")
    ap.add_argument("--slide", type=float, help="slide distance [mm] (default 3 Rd)")
    ap.add_argument("--indent-increments", type=int, default=4)
    ap.add_argument("--slide-increments", type=int, default=120,
                    help="equal increments of the slide (default 120: 1.25 master segments each)")
    ap.add_argument("--master-size", type=float, default=0.1,
                    help="master segment length along the track [mm] (default 0.1)")
    ap.add_argument("--slave-size", type=float, default=0.05,
                    help="die element size near its lowest point [mm] (default 0.05)")
    ap.add_argument("--slave-width", type=float, default=1.0, help="slave faces within this |x - X0| [mm]")
    ap.add_argument("--die-modulus", type=float, default=1.0, help="die E in units of the block's E (default 1)")
    ap.add_argument("--die-as-master", action="store_true",
                    help="the die's arc (surface SLAVE) is the master and the block's track (surface MASTER) "
                         "the slave: the stiffer body as the master, as ABAQUS advises for a stiff die")
    ap.add_argument("--margin", type=float, default=10.0, help="block beyond the track ends, and X0 [mm] (default 10)")
    ap.add_argument("--depth", type=float, default=10.0, help="block depth H [mm] (default 10)")
    ap.add_argument("--track-depth", type=float, default=0.5,
                    help="depth of the uniform layer of master-size elements under the track [mm] (default 0.5)")
    ap.add_argument("--growth", type=float, default=0.3, help="element size growth per unit distance (default 0.3)")
    ap.add_argument("--controls", type=float, nargs=2, metavar=("R_n", "C_n"),
                    help="write *CONTROLS, PARAMETERS=FIELD with these in each step (both codes read it)")
    ap.add_argument("--gmsh", default="gmsh")
    ap.add_argument("--json", help="also write the mesh parameters to this JSON file")
    opts = ap.parse_args(argv)
    if opts.slide is None:
        opts.slide = 3.0 * opts.radius
    opts.master_element = opts.master_element or opts.element
    with tempfile.TemporaryDirectory(prefix="ironing_gmsh_") as work:
        mesh = build_mesh(opts, work)
    info = write_deck(opts.out, mesh, opts)
    if opts.json:
        with open(opts.json, "w") as f:
            json.dump(info, f, indent=2)
    print(f"{opts.out}: die {info['die_element']} block {info['block_element']}  nodes {info['nodes']}  "
          f"elements {info['elements']}  dofs {info['dofs']}  slave nodes {info['slave_nodes']}  "
          f"master segments {info['master_faces']} ({info['master_segment'][0]:.4g}..{info['master_segment'][1]:.4g} mm)  "
          f"{info['segments_per_increment']:.1f} segments per slide increment")
    return 0


if __name__ == "__main__":
    sys.exit(main())
