#!/usr/bin/env python3
"""Figure of the user-constraint example: two squares tied by the plug-in.

Usage (after building the plug-in and `tether run equal_displacement.inp` here):
    python3 plot_equal_displacement.py [RESULT_DIR] [OUTPUT.png]
RESULT_DIR defaults to ./equal_displacement, OUTPUT.png to
./equal_displacement.png. Draws the reference and deformed (true scale) meshes
from the last .vtu (meshio), colours the elements by sigma_xx, and draws the
tie forces (CONSTRAINT_FORCE) and the applied loads. The multipliers of the
four ties are taken from the .dat (tools/tethertools/dat.py).
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
from matplotlib.collections import PolyCollection  # noqa: E402


def main(argv):
    result_dir = argv[1] if len(argv) > 1 else os.path.join(HERE, "equal_displacement")
    output = argv[2] if len(argv) > 2 else os.path.join(HERE, "equal_displacement.png")
    root = ET.parse(os.path.join(result_dir, "equal_displacement.pvd")).getroot()
    last = root.findall("./Collection/DataSet")[-1].get("file")
    mesh = meshio.read(os.path.join(result_dir, last))
    quads = np.concatenate([c.data for c in mesh.cells if c.type == "quad"])
    x0 = mesh.points[:, :2]
    x = x0 + mesh.point_data["U"][:, :2]
    sxx = np.concatenate(mesh.cell_data["S"])[:, 0]
    force = mesh.point_data["CONSTRAINT_FORCE"][:, :2]
    ids = mesh.point_data["NodeId"].astype(int)
    blocks = tethertools.dat.read(os.path.join(result_dir, "equal_displacement.dat"))
    lam = {b["set"]: b["rows"][0][3] for b in blocks if b["title"].startswith("constraint multipliers")}

    fig, ax = plt.subplots(figsize=(9, 4.2))
    ax.add_collection(PolyCollection([x0[q] for q in quads], facecolors="none", edgecolors="0.6", linestyles=":"))
    shifted = x.copy()
    shifted[ids >= 5] += np.array([0.25, 0.0])  # draw body B a little apart so both sides of the tie show
    polys = PolyCollection([shifted[q] for q in quads], array=sxx, cmap="viridis", edgecolors="k", clim=(90, 110))
    ax.add_collection(polys)
    fig.colorbar(polys, ax=ax, label="σ_xx (element mean, VTU)")
    for i in range(len(ids)):
        if np.linalg.norm(force[i]) > 1e-9:
            ax.arrow(*shifted[i], *(0.004 * force[i]), color="C3", width=0.012, length_includes_head=True)
        ax.annotate(str(ids[i]), shifted[i], textcoords="offset points", xytext=(-12, 4), fontsize=8)
    for i in np.where(np.isin(ids, [6, 7]))[0]:
        ax.arrow(*shifted[i], 0.2, 0, color="k", width=0.012, length_includes_head=True)
    ax.plot([], [], color="C3", lw=3, label="tie force on the node (CONSTRAINT_FORCE, ×0.004)")
    ax.plot([], [], color="k", lw=3, label="load 50 per node")
    text = "\n".join(f"{name}: λ = {value:+.4f}" for name, value in sorted(lam.items()))
    ax.text(0.02, 0.97, text, transform=ax.transAxes, va="top", fontsize=8, family="monospace")
    ax.set_aspect("equal")
    ax.set_xlim(-0.2, 2.9)
    ax.set_ylim(-0.35, 1.35)
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title("u_i(a) = u_i(b) by the plug-in: deformed (true scale; body B drawn shifted by 0.25)")
    fig.tight_layout()
    fig.savefig(output, dpi=110)
    print(f"{output}: sigma_xx {sxx.min():.6f}..{sxx.max():.6f}, u_x(node 6) = {x[list(ids).index(6), 0] - 2:.6f}, "
          f"lambda {lam}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
