#!/usr/bin/env python3
"""Writes the thick cylinder under internal pressure for aster-lite (.mail) and CalculiX (.inp).

A quarter of a long thick cylinder, inner radius a = 1, outer radius b = 2, plane
strain, elastic-perfectly plastic von Mises (E = 210000, NU = 0.3, SY = 240),
under an internal pressure raised linearly to P_MAX = 0.9 of the limit pressure
p_L = 2 SY / sqrt(3) ln(b / a) in 20 equal increments. Symmetry: DY = 0 on
Y = 0 (group BAS), DX = 0 on X = 0 (GAUCHE); the pressure acts on the inner edge
(group INT, SEG3 cells oriented with the outward normal of the cylinder). BAS
and GAUCHE are also groups of SEG3 cells, so that a refined mesh (MACR_ADAP_MAIL)
keeps its boundary conditions on every new node.

The mesh is a structured grid of QUAD8 cells, NT around the quarter circle and
NR across the wall, uniform in angle and radius; every node lies on its exact
circle. Unknowns: about 6 NT NR (NT = 256, NR = 256: 0.4 M). thick_cylinder_creep.py
writes the same mesh (write_mesh) for the creep benchmark.

usage: thick_cylinder.py NT NR OUTPUT.mail OUTPUT.inp
       thick_cylinder.py --frd-ux RESULTS.frd OUTPUT.inp
         (prints the radial displacement of node A, (a, 0), in the last step of a .frd)
"""
import math
import sys

from quad8_files import frd_value, write_inp_mesh, write_mail

A, B = 1.0, 2.0
E, NU, SY = 210000.0, 0.3, 240.0
LIMIT = 2.0 * SY / math.sqrt(3.0) * math.log(B / A)
P_MAX = 0.9 * LIMIT
INCREMENTS = 20


def write_mesh(nt, nr, mail, inp, heading):
    """The NT x NR mesh: the .mail file `mail`, and the mesh part of the .inp into open file
    `inp` (nodes, elements EALL, node sets NBAS, NGAUCHE, NA). The inner edge is face 4 of
    elements 1 to NT."""
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
    bottom_segs = [[ids[(0, 2 * b)], ids[(0, 2 * b + 2)], ids[(0, 2 * b + 1)]] for b in range(nr)]
    left_segs = [[ids[(ni, 2 * b + 2)], ids[(ni, 2 * b)], ids[(ni, 2 * b + 1)]] for b in range(nr)]

    first = len(quads) + 1
    write_mail(mail, "Thick cylinder under internal pressure, quarter model, NT=%d NR=%d" % (nt, nr), coords, quads,
               inner + bottom_segs + left_segs,
               [("CYLINDRE", list(range(1, len(quads) + 1))), ("INT", list(range(first, first + nt))),
                ("BAS", list(range(first + nt, first + nt + nr))),
                ("GAUCHE", list(range(first + nt + nr, first + nt + 2 * nr)))],
               [("BAS", bottom), ("GAUCHE", left),
                ("A", [ids[(0, 0)]]),    # (a, 0)
                ("B", [ids[(0, nj)]])])  # (b, 0)

    write_inp_mesh(inp, heading, "CPE8", coords, quads, [("NBAS", bottom), ("NGAUCHE", left), ("NA", [ids[(0, 0)]])])


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--frd-ux":
        print("%.7g" % frd_value(sys.argv[2], sys.argv[3], "DISP"))
        return
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    nt, nr = int(sys.argv[1]), int(sys.argv[2])
    with open(sys.argv[4], "w") as f:
        write_mesh(nt, nr, sys.argv[3], f, "Thick cylinder, quarter model, NT=%d NR=%d, CPE8" % (nt, nr))
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
