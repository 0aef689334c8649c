#!/usr/bin/env python3
"""Writes the plate-with-a-hole benchmark mesh for aster-lite (.mail) and CalculiX (.inp).

A quarter of a square plate of half-width L = 20 with a circular hole of radius
a = 1 at its centre, under a remote tension S = 1 along X (plane stress,
E = 1, NU = 0.3). Symmetry: DY = 0 on Y = 0, DX = 0 on X = 0;
the traction S on the edge X = L.

The mesh is one structured grid of QUAD8 cells, NT along the hole's quarter
circle and NR from the hole to the outer edges: grid line i joins the point of
the hole at angle theta = i / NT * pi / 2 to the point of the outer boundary
(X = L, then Y = L) at the same fraction of its length; along that line the
cells grow geometrically (ratio GROWTH from the hole to the outer edge).
Mid-side nodes lie on the exact circle at the hole.

Unknowns: about 12 NT NR (NT = 128, NR = 256: 0.4 M; NT = 256, NR = 512: 1.6 M).

usage: plate_hole.py NT NR OUTPUT.mail OUTPUT.inp
       plate_hole.py --frd-sxx RESULTS.frd OUTPUT.inp
         (prints SXX at the top of the hole from CalculiX's nodal stresses)
"""
import math
import sys

from quad8_files import frd_value, write_inp_mesh, write_mail

A, L, S = 1.0, 20.0, 1.0
E, NU = 1.0, 0.3
GROWTH = 20.0  # outermost over innermost radial cell size


def radial(t):
    """The fraction of the way from the hole to the outer edge at parameter t in [0, 1]."""
    q = GROWTH ** 1.0  # geometric sizes from 1 to GROWTH
    return (q ** t - 1.0) / (q - 1.0)


def point(s, t):
    """The point at circumferential parameter s in [0, 2] and radial parameter t in [0, 1]."""
    theta = s * math.pi / 4.0
    inner = (A * math.cos(theta), A * math.sin(theta))
    outer = (L, L * s) if s <= 1.0 else (L * (2.0 - s), L)
    g = radial(t)
    return ((1.0 - g) * inner[0] + g * outer[0], (1.0 - g) * inner[1] + g * outer[1])


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--frd-sxx":
        print("%.7g" % frd_value(sys.argv[2], sys.argv[3], "STRESS"))
        return
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    nt, nr = int(sys.argv[1]), int(sys.argv[2])
    mail, inp = sys.argv[3], sys.argv[4]
    ni, nj = 4 * nt, 2 * nr  # half steps: i along the hole, j outwards
    ids = {}
    coords = []
    for j in range(nj + 1):
        for i in range(ni + 1):
            if i % 2 == 1 and j % 2 == 1:
                continue  # no centre node in a QUAD8
            ids[(i, j)] = len(coords) + 1
            # 15 digits and no tiny residues of cos(pi/2): CalculiX reads at most 20
            # characters a number; both files get the same coordinates.
            coords.append(tuple(0.0 if abs(c) < 1e-12 else float("%.15g" % c)
                                for c in point(i / (2.0 * nt), j / float(nj))))
    quads = []
    for b in range(nr):
        for a in range(2 * nt):
            i, j = 2 * a, 2 * b
            # counterclockwise: i grows with theta (counterclockwise), j outwards,
            # so (i, j), (i, j+2), (i+2, j+2), (i+2, j) turns the right way round.
            corners = [(i, j), (i, j + 2), (i + 2, j + 2), (i + 2, j)]
            mids = [(i, j + 1), (i + 1, j + 2), (i + 2, j + 1), (i + 1, j)]
            quads.append([ids[p] for p in corners + mids])
    # Outer edge X = L: the cells of the last radial row with s <= 1 (a < nt);
    # their edge j = nj from i to i+2 is the face (2, 3) of the cell: nodes 2, 3, 6.
    right = [(nr - 1) * 2 * nt + a for a in range(nt)]
    bottom = [ids[(0, j)] for j in range(nj + 1)]
    left = [ids[(ni, j)] for j in range(nj + 1)]
    segs = [[ids[(2 * a, nj)], ids[(2 * a + 2, nj)], ids[(2 * a + 1, nj)]] for a in range(nt)]

    write_mail(mail, "Plate with a hole, quarter model, NT=%d NR=%d" % (nt, nr), coords, quads, segs,
               [("PLAQUE", list(range(1, len(quads) + 1))),
                ("DROITE", list(range(len(quads) + 1, len(quads) + len(segs) + 1)))],
               [("BAS", bottom), ("GAUCHE", left),
                ("A", [ids[(ni, 0)]]),   # (0, a): the top of the hole
                ("B", [ids[(0, 0)]])])   # (a, 0)

    with open(inp, "w") as f:
        write_inp_mesh(f, "Plate with a hole, quarter model, NT=%d NR=%d, CPS8" % (nt, nr), "CPS8", coords, quads,
                       [("NBAS", bottom), ("NGAUCHE", left), ("NA", [ids[(ni, 0)]])])
        f.write("*MATERIAL, NAME=ELAS\n*ELASTIC\n%g, %g\n" % (E, NU))
        # CalculiX expands CPS8 into a layer of 3D C3D20 bricks of this thickness: a
        # thickness of the hole's radius would be a 3D plate (2 % apart at the hole);
        # a thin one is plane stress. Pressures are per area: the answer is the same.
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=ELAS\n%g\n" % (A / 100.0))
        f.write("*BOUNDARY\nNBAS, 2, 2, 0.0\nNGAUCHE, 1, 1, 0.0\n")
        f.write("*STEP\n*STATIC\n*DLOAD\n")
        # A traction is a negative pressure on face 2 (nodes 2-3) of those cells.
        for c in right:
            f.write("%d, P2, %.15g\n" % (c + 1, -S))
        f.write("*NODE PRINT, NSET=NA\nU\n*EL FILE\nS\n*NODE FILE\nU\n*END STEP\n")


if __name__ == "__main__":
    main()
