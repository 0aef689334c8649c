#!/usr/bin/env python3
"""Writes the SVK square benchmark as a CalculiX input file (.inp).

The same problem as bench/svk_square.cpp: the unit square meshed by N x N CPE8
(QUAD8, plane strain, unit thickness), E = 1, NU = 0.3, geometric nonlinearity
(NLGEOM), bottom edge clamped, top edge displaced by (0.02, -0.015) in 5 equal
DIRECT increments. The total reaction on the top edge is printed to the .dat file.

usage: svk_square_inp.py N OUTPUT.inp
"""
import sys


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    n = int(sys.argv[1])
    out = sys.argv[2]
    h = 1.0 / n
    # Nodes on the (2n+1) x (2n+1) grid of half steps, without the cell centres.
    ids = {}
    lines = ["*HEADING", "SVK square N=%d, CPE8, NLGEOM, 5 DIRECT increments" % n, "*NODE, NSET=NALL"]
    for j in range(2 * n + 1):
        for i in range(2 * n + 1):
            if i % 2 == 1 and j % 2 == 1:
                continue
            ids[(i, j)] = len(ids) + 1
            lines.append("%d, %.17g, %.17g, 0" % (ids[(i, j)], i * h / 2, j * h / 2))
    lines.append("*ELEMENT, TYPE=CPE8, ELSET=EALL")
    e = 0
    for b in range(n):
        for a in range(n):
            i, j = 2 * a, 2 * b
            corners = [(i, j), (i + 2, j), (i + 2, j + 2), (i, j + 2)]
            mids = [(i + 1, j), (i + 2, j + 1), (i + 1, j + 2), (i, j + 1)]
            e += 1
            lines.append("%d, " % e + ", ".join(str(ids[p]) for p in corners + mids))

    def node_set(name, j):
        lines.append("*NSET, NSET=%s" % name)
        row = [str(ids[(i, j)]) for i in range(2 * n + 1)]
        for k in range(0, len(row), 16):
            lines.append(", ".join(row[k:k + 16]))

    node_set("NBOT", 0)
    node_set("NTOP", 2 * n)
    lines += [
        "*MATERIAL, NAME=SVK",
        "*ELASTIC",
        "1.0, 0.3",
        "*SOLID SECTION, ELSET=EALL, MATERIAL=SVK",
        "1.0",
        "*BOUNDARY",
        "NBOT, 1, 2, 0.0",
        "*STEP, NLGEOM, INC=1000",
        "*STATIC, DIRECT",
        "0.2, 1.0",
        "*BOUNDARY",
        "NTOP, 1, 1, 0.02",
        "NTOP, 2, 2, -0.015",
        "*NODE PRINT, NSET=NTOP, TOTALS=ONLY",
        "RF",
        "*END STEP",
    ]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
