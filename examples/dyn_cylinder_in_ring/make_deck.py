#!/usr/bin/env python3
"""Writes the cylinder-in-a-ring deck: an elastic cylinder (diameter 0.4 m,
E 2e8 Pa, nu 0.29, rho 1000, depth 0.1 m) slides without friction inside a
fixed steel ring (inner diameter 1.8 m, outer 2 m, E 2.069e11, nu 0.29,
rho 7850) under gravity (g = 9.80665), released at rest with its centre
level with the ring's centre. Plane strain, thickness 0.1 m.

    python3 make_deck.py [options] > cylinder_in_ring.inp

The cylinder is an O-grid of CPE8 (or CPE4: a core square of n x n, four
blocks of n x m to the circle); the ring is CPE8 (quadratic master segments: the
circle to about 1e-7 m), held at every node (--ring held: a rigid ring) or
at its outer face only (--ring outer: the steel ring deforms).
Closed form: the centre falls 0.7 m, so the energy is m g 0.7 = 86.2632 J
and the speed at the bottom sqrt(2 g 0.7) = 3.705 m/s.
"""
import argparse
import math

R_CYL, R_IN, R_OUT, DEPTH, G = 0.2, 0.9, 1.0, 0.1, 9.80665


class Mesh:
    """Nodes shared within a body (merged by position), never between bodies."""

    def __init__(self):
        self.nodes = {}  # (body, rounded coordinates) -> label
        self.coords = []
        self.body = 0

    def node(self, x, y):
        key = (self.body, round(x, 10), round(y, 10))
        if key not in self.nodes:
            self.coords.append((x, y))
            self.nodes[key] = len(self.coords)
        return self.nodes[key]


def cylinder(mesh, centre, n, m, quadratic):
    """Element rows (counter-clockwise; CPE8 when `quadratic`, its mid-side
    nodes on the circle along the surface) of the O-grid and the outer faces
    (element index, face)."""
    a = 0.45 * R_CYL / math.sqrt(2)  # core half-width
    cx, cy = centre
    rows, outer = [], []

    def element(point, i, k):
        """Corners (0,0), (1,0), (1,1), (0,1) of cell (i, k) of a block mapped by point(u, v), and mid-sides."""
        ref = [(0, 0), (1, 0), (1, 1), (0, 1)] + ([(0.5, 0), (1, 0.5), (0.5, 1), (0, 0.5)] if quadratic else [])
        return [mesh.node(*point(i + du, k + dv)) for du, dv in ref]

    def core(u, v):
        return cx - a + 2 * a * u / n, cy - a + 2 * a * v / n

    for k in range(n):
        for i in range(n):
            rows.append(element(core, i, k))
    corners = [(a, -a), (a, a), (-a, a), (-a, -a)]
    for side in range(4):  # the blocks from each core edge (v = 0) to its quarter of the circle (v = m)
        p0, p1 = corners[side], corners[(side + 1) % 4]
        th0 = -math.pi / 4 + side * math.pi / 2

        def block(u, v, p0=p0, p1=p1, th0=th0):
            s, t = u / n, v / m
            th = th0 + s * math.pi / 2
            ex, ey = p0[0] + s * (p1[0] - p0[0]), p0[1] + s * (p1[1] - p0[1])
            return cx + (1 - t) * ex + t * R_CYL * math.cos(th), cy + (1 - t) * ey + t * R_CYL * math.sin(th)

        for k in range(m):
            for i in range(n):
                # (u, v) -> (-v, u) order keeps the cell counter-clockwise: corners (i,k), (i,k+1), (i+1,k+1), (i+1,k)
                rows.append(element(lambda du, dv, i=i, k=k, block=block: block(i + dv, k + du), 0, 0))
                if k == m - 1:
                    outer.append((len(rows) - 1, 2))  # corners 2-3 are on the circle
    for q in rows:
        x = [mesh.coords[v - 1] for v in q[:4]]
        area = sum(x[k][0] * x[(k + 1) % 4][1] - x[(k + 1) % 4][0] * x[k][1] for k in range(4))
        assert area > 0, "clockwise element"
    return rows, outer


def ring(mesh, n_theta):
    """CPE8 rows of the annulus: corners (r_in, j), (r_out, j), (r_out, j+1), (r_in, j+1); face S4 on r_in."""
    def at(r, th):
        return mesh.node(r * math.cos(th), r * math.sin(th))

    rows, r_mid = [], 0.5 * (R_IN + R_OUT)
    for j in range(n_theta):
        t0, t1 = 2 * math.pi * j / n_theta, 2 * math.pi * (j + 1) / n_theta
        tm = 0.5 * (t0 + t1)
        rows.append([at(R_IN, t0), at(R_OUT, t0), at(R_OUT, t1), at(R_IN, t1),
                     at(r_mid, t0), at(R_OUT, tm), at(r_mid, t1), at(R_IN, tm)])
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--core", type=int, default=4, help="elements along an edge of the cylinder's core square (even)")
    parser.add_argument("--layers", type=int, default=3, help="elements from the core to the cylinder's surface")
    parser.add_argument("--cylinder-element", choices=("CPE4", "CPE8"), default="CPE8",
                        help="CPE8: the cylinder's surface is the circle (mass exact); CPE4: a polygon")
    parser.add_argument("--ring-elements", type=int, default=64, help="CPE8 around the ring")
    parser.add_argument("--ring", choices=("held", "outer"), default="held", help="hold every ring node, or its outer face")
    parser.add_argument("--period", type=float, default=0.7, help="step time [s]")
    parser.add_argument("--procedure", choices=("explicit", "implicit"), default="explicit")
    parser.add_argument("--increment", type=float, default=1e-3, help="implicit: the fixed time increment [s]")
    args = parser.parse_args()

    mesh = Mesh()
    cyl, outer = cylinder(mesh, (-(R_IN - R_CYL), 0.0), args.core, args.layers, args.cylinder_element == "CPE8")
    n_cyl_nodes = len(mesh.coords)
    mesh.body = 1
    rows = ring(mesh, args.ring_elements)
    out = ["*HEADING",
           "Cylinder sliding without friction inside a fixed ring under gravity (examples/dyn_cylinder_in_ring/make_deck.py "
           f"--cylinder-element {args.cylinder_element} --core {args.core} --layers {args.layers} --ring-elements {args.ring_elements} --ring {args.ring} "
           f"--period {args.period:g} --procedure {args.procedure})", "*NODE"]
    out += [f"{k + 1}, {x:.17g}, {y:.17g}" for k, (x, y) in enumerate(mesh.coords)]
    out.append(f"*ELEMENT, TYPE={args.cylinder_element}, ELSET=CYLINDER")
    out += [f"{e + 1}, " + ", ".join(map(str, q)) for e, q in enumerate(cyl)]
    first_ring = 10001
    out.append("*ELEMENT, TYPE=CPE8, ELSET=RING")
    out += [f"{first_ring + e}, " + ", ".join(map(str, r)) for e, r in enumerate(rows)]
    if args.core % 2:
        raise SystemExit("--core must be even (the cylinder's centre is a node)")
    out.append("*NSET, NSET=CENTRE")
    out.append(str(mesh.nodes[(0, round(-(R_IN - R_CYL), 10), 0.0)]))
    out.append("*NSET, NSET=CYLN, GENERATE")
    out.append(f"1, {n_cyl_nodes}, 1")
    out.append("*NSET, NSET=RINGN, GENERATE")
    out.append(f"{n_cyl_nodes + 1}, {len(mesh.coords)}, 1")
    outer_nodes = sorted({v for r in rows for v in (r[1], r[2], r[5])})
    out.append("*NSET, NSET=RINGOUT")
    out += [", ".join(map(str, outer_nodes[k:k + 12])) for k in range(0, len(outer_nodes), 12)]
    out.append("*SURFACE, NAME=CYLSURF")
    out += [f"{e + 1}, S{f}" for e, f in outer]
    out.append("*SURFACE, NAME=RINGIN")
    out += [f"{first_ring + e}, S4" for e in range(len(rows))]
    out += ["*MATERIAL, NAME=CYLMAT", "*ELASTIC", "2e8, 0.29", "*DENSITY", "1000.",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", "2.069e11, 0.29", "*DENSITY", "7850.",
            f"*SOLID SECTION, ELSET=CYLINDER, MATERIAL=CYLMAT", f"{DEPTH}",
            f"*SOLID SECTION, ELSET=RING, MATERIAL=STEEL", f"{DEPTH}",
            "*SURFACE INTERACTION, NAME=FRICTIONLESS",
            "*CONTACT PAIR, INTERACTION=FRICTIONLESS, TYPE=NODE TO SURFACE", "CYLSURF, RINGIN",
            "*BOUNDARY", ("RINGN" if args.ring == "held" else "RINGOUT") + ", 1, 2",
            "*STEP, NLGEOM" if args.procedure == "explicit" else "*STEP, NLGEOM, INC=100000"]
    if args.procedure == "explicit":
        out += ["*DYNAMIC, EXPLICIT", f", {args.period:g}"]
    else:
        out += ["*DYNAMIC, DIRECT", f"{args.increment:g}, {args.period:g}"]
    out += ["*DLOAD", f"CYLINDER, GRAV, {G}, 0., -1."]
    if args.procedure == "explicit":  # 100 points of history (an explicit step's default: 20)
        out += ["*OUTPUT, HISTORY, NUMBER INTERVAL=100", "*NODE OUTPUT, NSET=CENTRE", "U, V", "*END STEP"]
    else:
        out += ["*NODE PRINT, NSET=CENTRE", "U, V", "*END STEP"]
    print("\n".join(out))


if __name__ == "__main__":
    main()
