#!/usr/bin/python3
"""Picture of the periodic laminate RVE (laminate_rve.png) from tether's VTU files.

Each step is drawn as the deformed cell repeated 3 x 3 times, which is
possible because the solution is periodic: u(X + k) = u(X) + H k for a cell
translation k, with H = [u(1001) u(1002)] read from the reference nodes.
Colour: sigma_xx when stretched along the layers (the layers carry
different stresses at the same strain), epsilon_yy when stretched across them
(the layers carry the same stress at different strains).
Run after `tether run laminate_rve.inp` in this folder.
"""
import meshio
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
import numpy as np

MAGNIFY = 150.0
STEPS = [("laminate_rve/laminate_rve_1_1.vtu", "sxx", "along the layers: $H_{11}=10^{-3}$\ncolour $\\sigma_{xx}$ (the strain is uniform)"),
         ("laminate_rve/laminate_rve_2_1.vtu", "eyy", "across the layers: $H_{22}=10^{-3}$\ncolour $\\varepsilon_{yy}$ (the stress is uniform)")]


def element_values(mesh, quads, u, what):
    """sigma_xx (element average) or epsilon_yy from the nodal displacements (exact here)."""
    if what == "sxx":
        return mesh.cell_data_dict["S"]["quad"][:, 0]
    y = mesh.points[:, 1]
    return (u[quads[:, 2], 1] + u[quads[:, 3], 1] - u[quads[:, 1], 1] - u[quads[:, 0], 1]) / (
        2 * (y[quads[:, 3]] - y[quads[:, 0]]))


def main():
    fig, axes = plt.subplots(1, 2, figsize=(11, 5.2))
    for ax, (path, what, title) in zip(axes, STEPS):
        mesh = meshio.read(path)
        ids = mesh.point_data["NodeId"].astype(int)
        u = mesh.point_data["U"][:, :2]
        r1, r2 = np.where(ids == 1001)[0][0], np.where(ids == 1002)[0][0]
        H = np.column_stack([u[r1], u[r2]])
        quads = mesh.cells_dict["quad"]
        field = element_values(mesh, quads, u, what)
        polygons, values = [], []
        for kx in range(3):
            for ky in range(3):
                k = np.array([kx, ky], dtype=float)
                x = mesh.points[:, :2] + k + MAGNIFY * (u + H @ k)
                polygons += [x[q] for q in quads]
                values += list(field)
        pc = PolyCollection(polygons, array=np.array(values), cmap="viridis", edgecolors="k", linewidths=0.15)
        ax.add_collection(pc)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_title(title, fontsize=10)
        # Undeformed outline of the 3 x 3 cells.
        for c in range(4):
            ax.plot([c, c], [0, 3], "r--", lw=0.7)
            ax.plot([0, 3], [c, c], "r--", lw=0.7)
        fig.colorbar(pc, ax=ax, shrink=0.8, label="stress" if what == "sxx" else "strain")
    fig.suptitle(f"Periodic laminate RVE (3 x 3 cells, displacements x{MAGNIFY:g}; dashed: undeformed cells)")
    fig.tight_layout()
    fig.savefig("laminate_rve.png", dpi=110)


if __name__ == "__main__":
    main()
