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


def frd_sxx(frd, inp):
    """SXX at node A (the node of the set NA of the .inp) in the STRESS block of a .frd."""
    with open(inp) as f:
        lines = f.read().splitlines()
    node = int(lines[lines.index("*NSET, NSET=NA") + 1])
    in_stress = False
    with open(frd) as f:
        for line in f:
            if line.startswith(" -4"):
                in_stress = line.split()[1] == "STRESS"
            elif in_stress and line.startswith(" -1") and int(line[3:13]) == node:
                return float(line[13:25])
    sys.exit("no STRESS of node %d in %s" % (node, frd))


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--frd-sxx":
        print("%.7g" % frd_sxx(sys.argv[2], sys.argv[3]))
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

    with open(mail, "w") as f:
        f.write("TITRE\nPlate with a hole, quarter model, NT=%d NR=%d\nFINSF\n" % (nt, nr))
        f.write("COOR_2D\n")
        for k, (x, y) in enumerate(coords, 1):
            f.write("N%d %.15g %.15g\n" % (k, x, y))
        f.write("FINSF\nQUAD8\n")
        for k, q in enumerate(quads, 1):
            f.write("M%d %s\n" % (k, " ".join("N%d" % n for n in q)))
        f.write("FINSF\nSEG3\n")
        for k, s in enumerate(segs, len(quads) + 1):
            f.write("M%d %s\n" % (k, " ".join("N%d" % n for n in s)))
        f.write("FINSF\n")

        def group(kind, name, items, prefix):
            f.write("%s\n%s\n" % (kind, name))
            for k in range(0, len(items), 8):
                f.write(" ".join("%s%d" % (prefix, x) for x in items[k:k + 8]) + "\n")
            f.write("FINSF\n")

        group("GROUP_MA", "PLAQUE", list(range(1, len(quads) + 1)), "M")
        group("GROUP_MA", "DROITE", list(range(len(quads) + 1, len(quads) + len(segs) + 1)), "M")
        group("GROUP_NO", "BAS", bottom, "N")
        group("GROUP_NO", "GAUCHE", left, "N")
        group("GROUP_NO", "A", [ids[(ni, 0)]], "N")  # (0, a): the top of the hole
        group("GROUP_NO", "B", [ids[(0, 0)]], "N")   # (a, 0)
        f.write("FIN\n")

    with open(inp, "w") as f:
        f.write("*HEADING\nPlate with a hole, quarter model, NT=%d NR=%d, CPS8\n" % (nt, nr))
        f.write("*NODE, NSET=NALL\n")
        for k, (x, y) in enumerate(coords, 1):
            f.write("%d, %.15g, %.15g, 0\n" % (k, x, y))
        f.write("*ELEMENT, TYPE=CPS8, ELSET=EALL\n")
        for k, q in enumerate(quads, 1):
            f.write("%d, %s\n" % (k, ", ".join(str(n) for n in q)))

        def nset(name, nodes):
            f.write("*NSET, NSET=%s\n" % name)
            for k in range(0, len(nodes), 16):
                f.write(", ".join(str(n) for n in nodes[k:k + 16]) + "\n")

        nset("NBAS", bottom)
        nset("NGAUCHE", left)
        nset("NA", [ids[(ni, 0)]])
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
