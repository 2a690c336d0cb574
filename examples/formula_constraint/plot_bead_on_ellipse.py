#!/usr/bin/env python3
"""Figure of the formula-constraint example: a bead on an elliptical wire.

Usage (after `tether run bead_on_ellipse.inp` in this folder):
    python3 plot_bead_on_ellipse.py [RESULT_DIR] [OUTPUT.png]
RESULT_DIR defaults to ./bead_on_ellipse, OUTPUT.png to ./bead_on_ellipse.png.
Left: the bead's positions on the ellipse and the wire's force on it
(CONSTRAINT_FORCE from the .vtu files, read with meshio), which must be normal
to the ellipse. Right: lambda from the .dat against the exact P / (2|y|).
Needs python3-matplotlib and python3-meshio.
"""
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

A, B, P = 2.0, 1.0, 3.0
X0 = np.array([0.34729635533386083, -0.984807753012208])


def main(argv):
    result_dir = argv[1] if len(argv) > 1 else os.path.join(HERE, "bead_on_ellipse")
    output = argv[2] if len(argv) > 2 else os.path.join(HERE, "bead_on_ellipse.png")
    blocks = tethertools.dat.read(os.path.join(result_dir, "bead_on_ellipse.dat"))
    u = np.array([b["rows"][0][1:3] for b in blocks if b["title"].startswith("displacements") and b["set"] == "BEAD"])
    lam = np.array([b["rows"][0][3] for b in blocks
                    if b["title"].startswith("constraint multipliers") and b["set"] == "ELLIPSE"])
    x = X0 + u
    exact = P / (2 * np.abs(x[:, 1]))
    error = np.max(np.abs(lam / exact - 1))

    root = ET.parse(os.path.join(result_dir, "bead_on_ellipse.pvd")).getroot()
    files = [d.get("file") for d in root.findall("./Collection/DataSet")]
    worst_angle = 0.0
    forces = []
    for f in files:
        mesh = meshio.read(os.path.join(result_dir, f))
        p = mesh.points[0, :2] + mesh.point_data["U"][0, :2]
        force = mesh.point_data["CONSTRAINT_FORCE"][0, :2]
        normal = np.array([p[0] / A**2, p[1] / B**2])
        cross = (force[0] * normal[1] - force[1] * normal[0]) / (np.linalg.norm(force) * np.linalg.norm(normal))
        worst_angle = max(worst_angle, abs(np.degrees(np.arcsin(np.clip(cross, -1, 1)))))
        forces.append((p, force))

    fig, (ax_geo, ax_l) = plt.subplots(1, 2, figsize=(11, 4.6), gridspec_kw={"width_ratios": [1.3, 1]})
    s = np.linspace(0, 2 * np.pi, 300)
    ax_geo.plot(A * np.cos(s), B * np.sin(s), "-", color="0.6", lw=1.5, label="wire  x²/4 + y² = 1")
    ax_geo.plot(x[:, 0], x[:, 1], "o", color="C0", ms=4, label="bead, 20 increments")
    for p, force in forces[::3] + [forces[-1]]:
        ax_geo.arrow(p[0], p[1], 0.05 * force[0], 0.05 * force[1], color="C3", width=0.012,
                     length_includes_head=True)
    ax_geo.plot([], [], color="C3", lw=3, label="CONSTRAINT_FORCE (VTU) ×0.05")
    ax_geo.set_aspect("equal")
    ax_geo.set_xlim(-0.4, 2.6)
    ax_geo.set_ylim(-1.3, 0.45)
    ax_geo.set_title(f"wire force on the bead: normal to the wire to {worst_angle:.0e}°")
    ax_geo.legend(loc="upper left", fontsize=8)
    ax_geo.set_xlabel("x")
    ax_geo.set_ylabel("y")

    xs = np.linspace(0.3, 1.98, 200)
    ax_l.plot(xs, P / (2 * np.sqrt(1 - xs**2 / A**2)), "-", color="0.3", label="exact  λ = P / (2|y|)")
    ax_l.plot(x[:, 0], lam, "o", color="C3", label="tether  λ  (formula, .dat)")
    ax_l.set_xlabel("x of the bead")
    ax_l.set_ylabel("λ")
    ax_l.set_title(f"max |λ/exact − 1| = {error:.1e}")
    ax_l.grid(alpha=0.3)
    ax_l.legend()
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    print(f"{output}: lambda {lam[0]:.6f}..{lam[-1]:.6f}, max relative error {error:.2e}, "
          f"max angle between force and normal {worst_angle:.2e} deg")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
