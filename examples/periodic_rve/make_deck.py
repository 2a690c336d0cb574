#!/usr/bin/python3
"""Writes laminate_rve.inp: a periodic unit cell of a two-material laminate.

Unit cell [0,1] x [0,1], N x N CPE4 elements, material A (stiff, E_A) in the
bottom F_A of the cell, material B (soft, E_B) above it, nu = 0. *PERIODIC
pairs LEFT/RIGHT and BOTTOM/TOP; the reference nodes 1001 and 1002 carry the
columns of the macroscopic displacement gradient H. Step 1 stretches the cell
along the layers (H11 = STRAIN), step 2 across them (H22 = STRAIN).
"""
N, LAYERS_A = 16, 6          # F_A = 6/16 = 0.375
E_A, E_B, STRAIN = 1000.0, 100.0, 1e-3


def main():
    n = N
    out = ["*HEADING", f"Periodic laminate RVE: {LAYERS_A}/{N} of E={E_A:g}, the rest E={E_B:g}, nu=0",
           "*NODE, NSET=CELL"]
    label = lambda i, j: 1 + j * (n + 1) + i
    for j in range(n + 1):
        for i in range(n + 1):
            out.append(f"{label(i, j)}, {i / n:.17g}, {j / n:.17g}")
    out += ["** reference nodes: their displacements are the columns of H", "*NODE, NSET=REF",
            "1001, 1.5, 0.", "1002, 1.5, 1."]
    for name, rows in (("A", range(LAYERS_A)), ("B", range(LAYERS_A, n))):
        out.append(f"*ELEMENT, TYPE=CPE4, ELSET={name}")
        for j in rows:
            for i in range(n):
                out.append(f"{1 + j * n + i}, {label(i, j)}, {label(i + 1, j)}, {label(i + 1, j + 1)}, {label(i, j + 1)}")
    sides = {"LEFT": [label(0, k) for k in range(n + 1)], "RIGHT": [label(n, k) for k in range(n + 1)],
             "BOTTOM": [label(k, 0) for k in range(n + 1)], "TOP": [label(k, n) for k in range(n + 1)]}
    for name, nodes in sides.items():
        out.append(f"*NSET, NSET={name}")
        out += [", ".join(str(x) for x in nodes[k:k + 8]) for k in range(0, len(nodes), 8)]
    out += ["** u(b) - u(a) = H (X(b) - X(a)), H = [u(1001) u(1002)]; the corner pairs implied twice are dropped",
            "*PERIODIC, NAME=PBC, REFERENCE1=1001, REFERENCE2=1002", "LEFT, RIGHT", "BOTTOM, TOP",
            "*MATERIAL, NAME=STIFF", "*ELASTIC", f"{E_A:g}, 0.", "*MATERIAL, NAME=SOFT", "*ELASTIC", f"{E_B:g}, 0.",
            "*SOLID SECTION, ELSET=A, MATERIAL=STIFF", "1.", "*SOLID SECTION, ELSET=B, MATERIAL=SOFT", "1.",
            "** rigid motion: corner node 1 pinned, rotation removed by H21 = u_y(1001) = 0",
            "*BOUNDARY", "1, 1, 2", "1001, 2, 2, 0.",
            "*STEP, NAME=ALONG", "*STATIC", "*BOUNDARY", f"1001, 1, 1, {STRAIN:g}",
            "*NODE PRINT, NSET=REF", "U, RF", "*NODE FILE", "U, RF", "*EL FILE", "S, E", "*END STEP",
            "*STEP, NAME=ACROSS", "*STATIC", "*BOUNDARY, OP=NEW", "1, 1, 2", "1001, 2, 2, 0.", "1001, 1, 1, 0.",
            f"1002, 2, 2, {STRAIN:g}",
            "*NODE PRINT, NSET=REF", "U, RF", "*NODE FILE", "U, RF", "*EL FILE", "S, E", "*END STEP"]
    with open("laminate_rve.inp", "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
