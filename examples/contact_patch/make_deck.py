#!/usr/bin/python3
"""Writes the contact patch-test decks: a block pressed onto a block through a
flat interface whose meshes do not match.

Top block [0,1] x [1,2] (slave: its bottom faces), bottom block [0,1] x [0,1]
(master: its top faces), CPE4, E = 1000, nu = 0.3, 2 element rows each. A
pressure P = 10 on the top; the base on rollers (u_y = 0), one node of each
block held in x. The exact solution is uniform: contact pressure P everywhere.

  fine_on_coarse.inp   slave 7 elements on master 4 (slave = the finer side)
  coarse_on_fine.inp   slave 4 elements on master 6 (slave = the coarser side)
"""
import sys

P, E, NU = 10.0, 1000.0, 0.3


def block(first, x0, y0, nx, ny, elset):
    label = lambda i, j: first + j * (nx + 1) + i
    nodes = [f"{label(i, j)}, {x0 + i / nx:.17g}, {y0 + j / ny:.17g}" for j in range(ny + 1) for i in range(nx + 1)]
    elements = [f"{first + j * nx + i}, {label(i, j)}, {label(i + 1, j)}, {label(i + 1, j + 1)}, {label(i, j + 1)}"
                for j in range(ny) for i in range(nx)]
    return nodes, elements, label


def deck(n_top, n_bottom):
    tn, te, tl = block(1, 0.0, 1.0, n_top, 2, "TOP")
    bn, be, bl = block(1001, 0.0, 0.0, n_bottom, 2, "BOTTOM")
    out = ["*HEADING", f"contact patch test: slave {n_top} CPE4 on master {n_bottom} CPE4, pressure {P:g}",
           "*NODE"] + tn + bn
    out += ["*ELEMENT, TYPE=CPE4, ELSET=TOP"] + te + ["*ELEMENT, TYPE=CPE4, ELSET=BOTTOM"] + be
    out += ["*SURFACE, NAME=SLAVE"] + [f"{1 + i}, S1" for i in range(n_top)]
    out += ["*SURFACE, NAME=MASTER"] + [f"{1001 + n_bottom + i}, S3" for i in range(n_bottom)]
    out += ["*SURFACE INTERACTION, NAME=HARD", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD",
            "*CONTACT PAIR, INTERACTION=HARD, TYPE=NODE TO SURFACE", "SLAVE, MASTER",
            "*MATERIAL, NAME=M", "*ELASTIC", f"{E:g}, {NU:g}",
            "*SOLID SECTION, ELSET=TOP, MATERIAL=M", "*SOLID SECTION, ELSET=BOTTOM, MATERIAL=M",
            "*NSET, NSET=BASE"] + [str(bl(i, 0)) for i in range(n_bottom + 1)]
    out += ["*BOUNDARY", "BASE, 2", f"{bl(0, 0)}, 1", f"{tl(0, 2)}, 1",
            "*STEP", "*STATIC", "*DLOAD"] + [f"{1 + n_top + i}, P3, {P:g}" for i in range(n_top)]
    out += ["*CONTACT PRINT", "CSTR", "*NODE PRINT, NSET=BASE, TOTALS=ONLY", "RF", "*END STEP"]
    return "\n".join(out) + "\n"


def main():
    for name, (top, bottom) in {"fine_on_coarse": (7, 4), "coarse_on_fine": (4, 6)}.items():
        with open(f"{name}.inp", "w") as f:
            f.write(deck(top, bottom))
    return 0


if __name__ == "__main__":
    sys.exit(main())
