#!/usr/bin/env python3
"""Figure of the rigid-link example: tether's link force against N = P / sin(theta).

Usage (after `tether run rigid_link.inp` in this folder):
    python3 plot_rigid_link.py [RESULT_DIR] [OUTPUT.png]
RESULT_DIR defaults to ./rigid_link (where `tether run` writes), OUTPUT.png to
./rigid_link.png. Reads the .dat (tools/tethertools/dat.py) for lambda and the position
of B, and the .vtu files (meshio) for the CONSTRAINT_FORCE field.
Needs python3-matplotlib and python3-meshio.
"""
import math
import os
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
import tethertools.dat  # noqa: E402  (PYTHONPATH=../../tools)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

L, P = 2.0, 3.0
X_B0 = np.array([0.34729635533386083, -1.969615506024416])
TITLE = "constraint multipliers"


def main(argv):
    result_dir = argv[1] if len(argv) > 1 else os.path.join(HERE, "rigid_link")
    output = argv[2] if len(argv) > 2 else os.path.join(HERE, "rigid_link.png")
    blocks = tethertools.dat.read(os.path.join(result_dir, "rigid_link.dat"))
    u_b = [b["rows"][0][1:3] for b in blocks if b["title"].startswith("displacements") and b["set"] == "B"]
    lam = [b["rows"][0][3] for b in blocks if b["title"].startswith(TITLE) and b["set"] == "LINK"]
    x_b = X_B0 + np.array(u_b)
    theta = np.degrees(np.arctan2(-x_b[:, 1], x_b[:, 0]))
    lam = np.array(lam)
    exact = P / np.sin(np.radians(theta))
    error = np.max(np.abs(lam / exact - 1))

    root = ET.parse(os.path.join(result_dir, "rigid_link.pvd")).getroot()
    files = [d.get("file") for d in root.findall("./Collection/DataSet")]

    fig, (ax_geo, ax_n) = plt.subplots(1, 2, figsize=(11, 4.6), gridspec_kw={"width_ratios": [1, 1.25]})
    phi = np.linspace(0, -math.pi / 2, 100)
    ax_geo.plot(L * np.cos(phi), L * np.sin(phi), ":", color="0.6", lw=1)
    for k in (0, 6, 12, 19):
        mesh = meshio.read(os.path.join(result_dir, files[k]))
        x = mesh.points[:, :2] + mesh.point_data["U"][:, :2]
        force = mesh.point_data["CONSTRAINT_FORCE"][:, :2]
        ax_geo.plot(x[:, 0], x[:, 1], "-o", color="C0", lw=1.2, ms=4, alpha=0.6)
        scale = 0.06
        ax_geo.arrow(x[1, 0], x[1, 1], scale * force[1, 0], scale * force[1, 1], color="C3", width=0.03,
                     length_includes_head=True, zorder=5, alpha=0.8)
        ax_geo.arrow(x[1, 0], x[1, 1], 0, -scale * P, color="k", width=0.012, length_includes_head=True)
        ax_geo.annotate(f"θ = {theta[k]:.0f}°", x[1], textcoords="offset points", xytext=(6, 6), fontsize=8)
    ax_geo.plot([], [], color="C3", lw=3, label="CONSTRAINT_FORCE on B (VTU), ×0.06")
    ax_geo.plot([], [], color="k", lw=3, label="load P on B, ×0.06")
    ax_geo.plot(0, 0, "ks", ms=8)
    ax_geo.set_aspect("equal")
    ax_geo.set_xlim(-0.3, 2.4)
    ax_geo.set_ylim(-2.4, 0.9)
    ax_geo.set_title("rigid link A–B, B driven horizontally")
    ax_geo.legend(loc="upper right", fontsize=8)
    ax_geo.set_xlabel("x")
    ax_geo.set_ylabel("y")

    t = np.linspace(8, 80, 200)
    ax_n.plot(t, 1 / np.sin(np.radians(t)), "-", color="0.3", label="exact  N/P = 1/sin θ")
    ax_n.plot(theta, lam / P, "o", color="C3", label="tether  λ/P  (*MPC LINK, .dat)")
    ax_n.set_xlabel("θ  [deg below the horizontal]")
    ax_n.set_ylabel("link force / P")
    ax_n.set_title(f"link force, 20 increments: max |λ/N − 1| = {error:.1e}")
    ax_n.grid(alpha=0.3)
    ax_n.legend()
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    print(f"{output}: theta {theta[0]:.2f}..{theta[-1]:.2f} deg, lambda {lam[0]:.6f}..{lam[-1]:.6f}, "
          f"max relative error {error:.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
