"""Writes a deck of the NAFEMS CGS-4 frictional contact test (plane strain).

A block rests on a foundation whose top is a straight slope, tan(alpha) = 0.1;
it is pressed down by a vertical load G, then pushed horizontally up the slope
until the whole interface slides (Coulomb friction, mu = 0.3). Once it slides,
the equilibrium of the block gives the horizontal push F exactly:

    F / G = (tan(alpha) + mu) / (1 - mu tan(alpha))      (0.412371 for 0.1, 0.3)

whatever the deformation of the bodies, as long as the interface stays straight
and every point of it slips. The geometry is the one of the NAFEMS test as
FrontISTR's test suite models it (units are consistent, none implied):

  * foundation: 0 <= x <= 6 between y = 0 and the slope y = 0.7 + 0.1 x,
    12 x 3 CPE4 (element set FOUNDATION); its bottom (set BASE) is fixed;
  * block: 1 <= x <= 5 between the slope and y = 2, 9 x 3 CPE4 (element set
    BLOCK), so that its faces on the slope (4/9 long horizontally) do not
    match the foundation's (1/2 long): non-matching meshes;
  * both E = 1100, nu = 0, thickness 1;
  * contact: slave = the block's bottom faces (SLAVE), master = the
    foundation's top faces (MASTER), *SURFACE BEHAVIOR HARD (or, with
    --linear K, LINEAR: a penalty law both tether and CalculiX model),
    *FRICTION mu (none when mu = 0: then F / G = tan(alpha));
  * step 1 "LOAD": the vertical load G (--load, default 40) on the block's top
    (set TOP, the consistent nodal loads of a uniform pressure G / 4 over its
    width 4), the block's left side above the interface (set PUSH) held in x;
  * step 2 "PUSH": PUSH moved by --push (default 0.2) in x in --increments
    (default 10) equal increments; G stays.

F is the x reaction of PUSH; the test also checks it against the contact
force of the pair (the force of the foundation on the block).

The formula holds for rigid bodies. Contact acts on the deformed surfaces:
at G = 40 (pressure 10 on E = 1100, strains near 1 %) the foundation, thicker
and more loaded on the right, flattens the interface (its slope drops from 0.1
to about 0.098 between the block's ends), which lowers F/G by a few tenths of
a per cent. The deformation scales with G / E while the sliding does not:
--load 0.4 gives the rigid limit.

Usage: make_cgs4_deck.py OUT.inp [--type SURFACE TO SURFACE|NODE TO SURFACE]
                                 [--mu 0.3] [--linear K] [--load 40] [--push 0.2] [--increments 10]
"""
import argparse

TAN_ALPHA = 0.1
E, NU = 1100.0, 0.0
WIDTH = 4.0  # of the block


def slope(x):
    return 0.7 + TAN_ALPHA * x


def grid(first, xs, lower, upper, layers):
    """Nodes (label, x, y) of a structured grid; layer j between lower(x) and upper(x)."""
    nodes = []
    for j in range(layers + 1):
        for i, x in enumerate(xs):
            y = lower(x) + (upper(x) - lower(x)) * j / layers
            nodes.append((first + j * len(xs) + i, x, y))
    return nodes


def quads(first_node, first_element, nx, ny):
    """CPE4 connectivity (counter-clockwise) of an nx x ny grid."""
    out = []
    for l in range(ny):
        for k in range(nx):
            a = first_node + l * (nx + 1) + k
            out.append((first_element + l * nx + k, a, a + 1, a + 1 + nx + 1, a + nx + 1))
    return out


def fmt(v):
    return f"{v:.12g}"


def write(path, contact_type, mu, load, push, increments, linear=None):
    fx = [6.0 * i / 12 for i in range(13)]
    bx = [1.0 + 4.0 * i / 9 for i in range(10)]
    foundation = grid(1, fx, lambda x: 0.0, slope, 3)
    block = grid(101, bx, slope, lambda x: 2.0, 3)
    f_el = quads(1, 1, 12, 3)
    b_el = quads(101, 101, 9, 3)
    top = [n for n in block if abs(n[2] - 2.0) < 1e-12]
    h = WIDTH / 9
    lines = ["*HEADING",
             f"NAFEMS CGS-4: block pushed up a slope tan(alpha) = {TAN_ALPHA:g}, mu = {mu:g}, "
             f"G = {load:g}, {contact_type} (tools/make_cgs4_deck.py)",
             "*NODE"]
    lines += [f"{n}, {fmt(x)}, {fmt(y)}" for n, x, y in foundation + block]
    lines.append("*ELEMENT, TYPE=CPE4, ELSET=FOUNDATION")
    lines += [", ".join(str(v) for v in e) for e in f_el]
    lines.append("*ELEMENT, TYPE=CPE4, ELSET=BLOCK")
    lines += [", ".join(str(v) for v in e) for e in b_el]
    lines.append("*NSET, NSET=BASE")
    lines.append(", ".join(str(n) for n, x, y in foundation if y == 0.0))
    lines.append("*NSET, NSET=PUSH")
    lines.append(", ".join(str(n) for n, x, y in block if abs(x - 1.0) < 1e-12 and y > slope(1.0) + 1e-12))
    lines.append("*NSET, NSET=TOP")
    lines.append(", ".join(str(n) for n, x, y in top))
    lines.append("*SURFACE, NAME=SLAVE, TYPE=ELEMENT")
    lines += [f"{e[0]}, S1" for e in b_el[:9]]
    lines.append("*SURFACE, NAME=MASTER, TYPE=ELEMENT")
    lines += [f"{e[0]}, S3" for e in f_el[-12:]]
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", f"{fmt(E)}, {fmt(NU)}",
              "*SOLID SECTION, ELSET=FOUNDATION, MATERIAL=STEEL", "1.",
              "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL", "1.",
              "*SURFACE INTERACTION, NAME=ROUGH"]
    lines += ([f"*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", fmt(linear)] if linear
              else ["*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD"])
    lines += (["*FRICTION", fmt(mu)] if mu > 0 else [])
    lines += [f"*CONTACT PAIR, INTERACTION=ROUGH, TYPE={contact_type}", "SLAVE, MASTER",
              "*BOUNDARY", "BASE, 1, 2", "PUSH, 1, 1",
              "*STEP", "*STATIC", "1., 1.", "*CLOAD"]
    for n, x, y in top:
        end = abs(x - 1.0) < 1e-12 or abs(x - 5.0) < 1e-12
        lines.append(f"{n}, 2, {fmt(-load / WIDTH * h * (0.5 if end else 1.0))}")
    lines += ["*NODE PRINT, NSET=PUSH, TOTALS=ONLY", "RF", "*END STEP",
              "*STEP, INC=100", "*STATIC", f"{fmt(1.0 / increments)}, 1.",
              "*BOUNDARY", f"PUSH, 1, 1, {fmt(push)}",
              "*NODE PRINT, NSET=PUSH, TOTALS=ONLY", "RF", "*CONTACT PRINT", "CSTR", "*END STEP"]
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--type", default="SURFACE TO SURFACE", choices=["SURFACE TO SURFACE", "NODE TO SURFACE"])
    ap.add_argument("--mu", type=float, default=0.3)
    ap.add_argument("--linear", type=float, metavar="K",
                    help="PRESSURE-OVERCLOSURE=LINEAR with slope K [pressure/length] instead of HARD")
    ap.add_argument("--load", type=float, default=40.0, help="vertical load G on the block (default 40)")
    ap.add_argument("--push", type=float, default=0.2)
    ap.add_argument("--increments", type=int, default=10)
    a = ap.parse_args()
    write(a.out, a.type, a.mu, a.load, a.push, a.increments, a.linear)
    ratio = (TAN_ALPHA + a.mu) / (1 - a.mu * TAN_ALPHA)  # tan(alpha) when mu = 0
    print(f"wrote {a.out}: F/G exact {ratio:.6f}")


if __name__ == "__main__":
    main()
