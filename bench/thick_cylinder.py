#!/usr/bin/env python3
"""Writes the thick cylinder under internal pressure for aster-lite (.mail) and CalculiX (.inp).

A quarter of a long thick cylinder, inner radius a = 1, outer radius b = 2, plane
strain, elastic-perfectly plastic von Mises (E = 210000, NU = 0.3, SY = 240),
under an internal pressure raised linearly to P_MAX = 0.9 of the limit pressure
p_L = 2 SY / sqrt(3) ln(b / a) in 20 equal increments. Symmetry: DY = 0 on
Y = 0 (group BAS), DX = 0 on X = 0 (GAUCHE); the pressure acts on the inner edge
(group INT, SEG3 cells oriented with the outward normal of the cylinder).

The mesh is a structured grid of QUAD8 cells, NT around the quarter circle and
NR across the wall, uniform in angle and radius; every node lies on its exact
circle. Unknowns: about 6 NT NR (NT = 256, NR = 256: 0.4 M).

usage: thick_cylinder.py NT NR OUTPUT.mail OUTPUT.inp
       thick_cylinder.py --frd-ux RESULTS.frd OUTPUT.inp
         (prints the radial displacement of node A, (a, 0), in the last step of a .frd)
"""
import math
import sys

A, B = 1.0, 2.0
E, NU, SY = 210000.0, 0.3, 240.0
LIMIT = 2.0 * SY / math.sqrt(3.0) * math.log(B / A)
P_MAX = 0.9 * LIMIT
INCREMENTS = 20


def frd_ux(frd, inp):
    """UX of node A (the node of the set NA of the .inp) in the last DISP block of a .frd."""
    with open(inp) as f:
        lines = f.read().splitlines()
    node = int(lines[lines.index("*NSET, NSET=NA") + 1])
    in_disp, value = False, None
    with open(frd) as f:
        for line in f:
            if line.startswith(" -4"):
                in_disp = line.split()[1] == "DISP"
            elif in_disp and line.startswith(" -1") and int(line[3:13]) == node:
                value = float(line[13:25])
    if value is None:
        sys.exit("no DISP of node %d in %s" % (node, frd))
    return value


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--frd-ux":
        print("%.7g" % frd_ux(sys.argv[2], sys.argv[3]))
        return
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    nt, nr = int(sys.argv[1]), int(sys.argv[2])
    mail, inp = sys.argv[3], sys.argv[4]
    ni, nj = 2 * nt, 2 * nr  # half steps: i around (angle), j outwards (radius)
    ids, coords = {}, []
    for j in range(nj + 1):
        for i in range(ni + 1):
            if i % 2 == 1 and j % 2 == 1:
                continue  # no centre node in a QUAD8
            ids[(i, j)] = len(coords) + 1
            theta = i / float(ni) * math.pi / 2.0
            r = A + (B - A) * j / float(nj)
            # 15 digits and exact zeros on the axes: both files get the same coordinates.
            x = 0.0 if i == ni else float("%.15g" % (r * math.cos(theta)))
            y = 0.0 if i == 0 else float("%.15g" % (r * math.sin(theta)))
            coords.append((x, y))
    quads = []
    for b in range(nr):
        for a in range(nt):
            i, j = 2 * a, 2 * b
            # counterclockwise: outwards along i = const, then around.
            corners = [(i, j), (i, j + 2), (i + 2, j + 2), (i + 2, j)]
            mids = [(i, j + 1), (i + 1, j + 2), (i + 2, j + 1), (i + 1, j)]
            quads.append([ids[p] for p in corners + mids])
    # The inner edge of the first row of cells: their face 4 (corners 4, 1), which runs
    # clockwise around the axis: the outward normal of the cylinder points to the axis.
    inner = [[ids[(2 * a + 2, 0)], ids[(2 * a, 0)], ids[(2 * a + 1, 0)]] for a in range(nt)]
    bottom = [ids[(0, j)] for j in range(nj + 1)]
    left = [ids[(ni, j)] for j in range(nj + 1)]

    with open(mail, "w") as f:
        f.write("TITRE\nThick cylinder under internal pressure, quarter model, NT=%d NR=%d\nFINSF\n" % (nt, nr))
        f.write("COOR_2D\n")
        for k, (x, y) in enumerate(coords, 1):
            f.write("N%d %.15g %.15g\n" % (k, x, y))
        f.write("FINSF\nQUAD8\n")
        for k, q in enumerate(quads, 1):
            f.write("M%d %s\n" % (k, " ".join("N%d" % n for n in q)))
        f.write("FINSF\nSEG3\n")
        for k, s in enumerate(inner, len(quads) + 1):
            f.write("M%d %s\n" % (k, " ".join("N%d" % n for n in s)))
        f.write("FINSF\n")

        def group(kind, name, items, prefix):
            f.write("%s\n%s\n" % (kind, name))
            for k in range(0, len(items), 8):
                f.write(" ".join("%s%d" % (prefix, x) for x in items[k:k + 8]) + "\n")
            f.write("FINSF\n")

        group("GROUP_MA", "CYLINDRE", list(range(1, len(quads) + 1)), "M")
        group("GROUP_MA", "INT", list(range(len(quads) + 1, len(quads) + len(inner) + 1)), "M")
        group("GROUP_NO", "BAS", bottom, "N")
        group("GROUP_NO", "GAUCHE", left, "N")
        group("GROUP_NO", "A", [ids[(0, 0)]], "N")    # (a, 0)
        group("GROUP_NO", "B", [ids[(0, nj)]], "N")   # (b, 0)
        f.write("FIN\n")

    with open(inp, "w") as f:
        f.write("*HEADING\nThick cylinder, quarter model, NT=%d NR=%d, CPE8\n" % (nt, nr))
        f.write("*NODE, NSET=NALL\n")
        for k, (x, y) in enumerate(coords, 1):
            f.write("%d, %.15g, %.15g, 0\n" % (k, x, y))
        f.write("*ELEMENT, TYPE=CPE8, ELSET=EALL\n")
        for k, q in enumerate(quads, 1):
            f.write("%d, %s\n" % (k, ", ".join(str(n) for n in q)))

        def nset(name, nodes):
            f.write("*NSET, NSET=%s\n" % name)
            for k in range(0, len(nodes), 16):
                f.write(", ".join(str(n) for n in nodes[k:k + 16]) + "\n")

        nset("NBAS", bottom)
        nset("NGAUCHE", left)
        nset("NA", [ids[(0, 0)]])
        f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n%g, %g\n*PLASTIC\n%g, 0.0\n" % (E, NU, SY))
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n%g\n" % (A / 100.0))
        f.write("*BOUNDARY\nNBAS, 2, 2, 0.0\nNGAUCHE, 1, 1, 0.0\n")
        # The same 20 increments as aster-lite, none cut or added.
        f.write("*STEP, INC=1000\n*STATIC, DIRECT\n%g, 1.0\n*DLOAD\n" % (1.0 / INCREMENTS))
        for c in range(nt):  # face 4 (nodes 4-1) of the first row of cells
            f.write("%d, P4, %.15g\n" % (c + 1, P_MAX))
        f.write("*NODE PRINT, NSET=NA\nU\n*NODE FILE\nU\n*END STEP\n")


if __name__ == "__main__":
    main()
