#!/usr/bin/env python3
"""Pressure against displacement and the plastic zone of the thick cylinder.

    plot_cylinder.py cylinder.inp cylinder/cylinder.dat [--vtu cylinder/cylinder_1_20.vtu] [--png cylinder.png]

Reads the node coordinates from the deck and, from the .dat, the
displacements of the sets INNER (the bore, r = a) and OUTER (r = b) at every
increment; the bore pressure is 190 t in step 1 (total time t) and
190 (2 - t) in step 2. Prints, per increment, the pressure, the mean radial
displacement of each set, the number of yielding points (AC YIELD) and, for
the outer radius, Hill's closed form. With --png: pressure against the bore
and the outer displacement beside the closed forms, and, from --vtu, the
nodal PEEQ of the loaded state with Hill's plastic radius.

Closed forms (plane strain, von Mises, no hardening, k = sigma_y / sqrt 3,
Hill's assumption sigma_z = (sigma_r + sigma_theta)/2 in the plastic zone):
  the plastic zone reaches r = c at   p(c) = k (2 ln(c/a) + 1 - c^2/b^2),
  the outer radius then moves         u(b) = 2 (1 - nu^2) k c^2 / (E b),
  the limit pressure (c = b) is       p_L = 2 k ln(b/a);
elastic (p below p(a)):               u(r) = (1+nu) p a^2 ((1-2nu) r + b^2/r) / (E (b^2 - a^2)).
"""
import argparse
import math
import re

A, B, E, NU, SY, P_MAX = 10.0, 20.0, 200000.0, 0.3, 240.0, 190.0
K = SY / math.sqrt(3)


def hill_pressure(c):
    return K * (2 * math.log(c / A) + 1 - c * c / (B * B))


def hill_radius(p):
    """c with hill_pressure(c) = p (a <= c <= b), by bisection; None below first yield."""
    if p < hill_pressure(A):
        return None
    lo, hi = A, B
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if hill_pressure(mid) < p else (lo, mid)
    return 0.5 * (lo + hi)


def elastic_u(p, r):
    return (1 + NU) * p * A * A * ((1 - 2 * NU) * r + B * B / r) / (E * (B * B - A * A))


def hill_u_outer(p):
    c = hill_radius(p)
    return elastic_u(p, B) if c is None else 2 * (1 - NU * NU) * K * c * c / (E * B)


def coordinates(deck):
    nodes, reading = {}, False
    for line in open(deck):
        if line.startswith("*"):
            reading = line.upper().startswith("*NODE") and not line.upper().startswith("*NODE ")
            continue
        if reading and line.strip():
            f = line.split(",")
            nodes[int(f[0])] = (float(f[1]), float(f[2]))
    return nodes


def history(dat, nodes):
    """Per increment: (time, pressure, u_r at a, u_r at b, yielding points)."""
    text = open(dat).read()
    blocks = re.split(r"\n(?= \S)", text)
    rows, current = {}, None
    for block in blocks:
        if not block.strip():
            continue
        head = block.strip().splitlines()[0]
        m = re.search(r"for set (\S+) and time\s+(\S+)", head)
        if not m:
            continue
        t = float(m.group(2))
        row = rows.setdefault(t, {"INNER": None, "OUTER": None, "yield": 0})
        values = [ln.split() for ln in block.strip().splitlines()[1:] if ln.strip()]
        if head.startswith("displacements") and m.group(1) in ("INNER", "OUTER"):
            ur = [(nodes[int(v[0])][0] * float(v[1]) + nodes[int(v[0])][1] * float(v[2])) / math.hypot(*nodes[int(v[0])])
                  for v in values]
            row[m.group(1)] = sum(ur) / len(ur)
        elif head.startswith("actively yielding"):
            row["yield"] = sum(1 for v in values if float(v[2]) > 0.5)
    out = []
    for t in sorted(rows):
        p = P_MAX * t if t <= 1 + 1e-12 else P_MAX * (2 - t)
        out.append((t, p, rows[t]["INNER"], rows[t]["OUTER"], rows[t]["yield"]))
    return out


def plot(rows, vtu, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2 if vtu else 1, figsize=(11 if vtu else 6, 4.5))
    ax = axes[0] if vtu else axes
    load = [r for r in rows if r[0] <= 1 + 1e-12]
    ax.plot([0] + [r[2] for r in rows], [0] + [r[1] for r in rows], "o-", ms=3, label="tether, bore r = a")
    ax.plot([0] + [r[3] for r in rows], [0] + [r[1] for r in rows], "s-", ms=3, label="tether, outer r = b")
    ps = [P_MAX * i / 200 for i in range(201)]
    ax.plot([hill_u_outer(p) for p in ps], ps, "k--", lw=1, label="Hill, outer r = b")
    ax.plot([elastic_u(p, A) for p in ps], ps, "k:", lw=1, label="elastic, bore")
    p_limit = 2 * K * math.log(B / A)
    ax.axhline(p_limit, color="grey", lw=0.8)
    ax.text(0.0005, p_limit + 2, f"limit pressure {p_limit:.2f} MPa", fontsize=8)
    ax.set_xlabel("radial displacement [mm]")
    ax.set_ylabel("bore pressure [MPa]")
    ax.set_ylim(0, 205)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="lower right")
    if vtu:
        import matplotlib.tri as mtri
        import meshio
        mesh = meshio.read(vtu)
        x, y = mesh.points[:, 0], mesh.points[:, 1]
        tri = mtri.Triangulation(x, y)
        cx, cy = x[tri.triangles].mean(axis=1), y[tri.triangles].mean(axis=1)
        tri.set_mask(cx * cx + cy * cy < (A * 1.001) ** 2)
        ax2 = axes[1]
        cs = ax2.tricontourf(tri, mesh.point_data["PEEQ"], levels=12, cmap="viridis")
        fig.colorbar(cs, ax=ax2, label="PEEQ (nodal)")
        c = hill_radius(load[-1][1])
        th = [0.5 * math.pi * i / 100 for i in range(101)]
        ax2.plot([c * math.cos(t) for t in th], [c * math.sin(t) for t in th], "w--", lw=1.5,
                 label=f"Hill's plastic radius c = {c:.2f} mm")
        ax2.set_aspect("equal")
        ax2.set_title(f"p = {load[-1][1]:.0f} MPa", fontsize=9)
        ax2.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("deck")
    ap.add_argument("dat")
    ap.add_argument("--vtu")
    ap.add_argument("--png")
    opts = ap.parse_args()
    rows = history(opts.dat, coordinates(opts.deck))
    print(" time    p [MPa]   u(a) [mm]    u(b) [mm]   Hill u(b)  yielding points")
    for t, p, ua, ub, n in rows:
        print(f"{t:5.2f} {p:9.2f} {ua:12.6e} {ub:12.6e} {hill_u_outer(p) if t <= 1 + 1e-12 else float('nan'):12.6e} {n:6d}")
    if opts.png:
        plot(rows, opts.vtu, opts.png)


if __name__ == "__main__":
    main()
