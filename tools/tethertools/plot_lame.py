#!/usr/bin/env python3
"""Plots a Lame cylinder result: hoop stress over the quarter ring, and the
radial profiles of sigma_rr and sigma_tt against the exact solution.

Usage: plot_lame.py RESULT.vtu OUT.png   (Debian's /usr/bin/python3: meshio, matplotlib)
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

from tethertools.make_lame_deck import A, B, P  # noqa: E402


def main():
    mesh = meshio.read(sys.argv[1])
    xy = mesh.points[:, :2]
    s = mesh.point_data["S"]  # XX, YY, ZZ, XY, YZ, XZ
    r = np.hypot(xy[:, 0], xy[:, 1])
    c, sn = xy[:, 0] / r, xy[:, 1] / r
    s_rr = s[:, 0] * c * c + s[:, 1] * sn * sn + 2 * s[:, 3] * c * sn
    s_tt = s[:, 0] * sn * sn + s[:, 1] * c * c - 2 * s[:, 3] * c * sn

    triangles = []
    for block in mesh.cells:
        corners = {"triangle": 3, "triangle6": 3, "quad": 4, "quad8": 4}[block.type]
        for cell in block.data:
            cell = cell[:corners]
            triangles.append(cell[[0, 1, 2]])
            if corners == 4:
                triangles.append(cell[[0, 2, 3]])
    tri = mtri.Triangulation(xy[:, 0], xy[:, 1], np.array(triangles))

    fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(11, 4.6))
    shaded = ax0.tripcolor(tri, s_tt, shading="gouraud", cmap="viridis")
    ax0.set_aspect("equal")
    ax0.set_title("tether: hoop stress $\\sigma_{\\theta\\theta}$ [MPa]")
    ax0.set_xlabel("x [mm]")
    ax0.set_ylabel("y [mm]")
    fig.colorbar(shaded, ax=ax0)

    k = P * A * A / (B * B - A * A)
    rr = np.linspace(A, B, 200)
    ax1.plot(rr, k * (1 + B * B / rr**2), "k-", label="exact $\\sigma_{\\theta\\theta}$")
    ax1.plot(rr, k * (1 - B * B / rr**2), "k--", label="exact $\\sigma_{rr}$")
    ax1.plot(r, s_tt, "o", ms=3, label="tether $\\sigma_{\\theta\\theta}$ (nodal)")
    ax1.plot(r, s_rr, "s", ms=3, label="tether $\\sigma_{rr}$ (nodal)")
    ax1.set_xlabel("r [mm]")
    ax1.set_ylabel("stress [MPa]")
    ax1.set_title(f"Lame cylinder, p = {P:g} MPa, plane strain")
    ax1.legend()
    ax1.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
