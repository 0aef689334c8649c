"""The files the QUAD8 benchmarks write and read: the mesh for aster-lite (code_aster's
.mail format), the mesh part of CalculiX's .inp, and a nodal value from CalculiX's .frd.
Imported by plate_hole.py, thick_cylinder.py and thick_cylinder_creep.py (run from this
folder's scripts).
"""
import sys


def write_mail(path, title, coords, quads, segs, cell_groups, node_groups):
    """coords: (x, y) per node (N1, N2, ...); quads then segs: node numbers per cell (M1, ...);
    cell_groups, node_groups: (name, numbers) pairs."""
    with open(path, "w") as f:
        f.write("TITRE\n%s\nFINSF\n" % title)
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
        for kind, prefix, groups in (("GROUP_MA", "M", cell_groups), ("GROUP_NO", "N", node_groups)):
            for name, items in groups:
                f.write("%s\n%s\n" % (kind, name))
                for k in range(0, len(items), 8):
                    f.write(" ".join("%s%d" % (prefix, x) for x in items[k:k + 8]) + "\n")
                f.write("FINSF\n")
        f.write("FIN\n")


def write_inp_mesh(f, heading, element_type, coords, quads, nsets):
    """The heading, nodes, elements (set EALL) and node sets of a CalculiX .inp, into open file f."""
    f.write("*HEADING\n%s\n" % heading)
    f.write("*NODE, NSET=NALL\n")
    for k, (x, y) in enumerate(coords, 1):
        f.write("%d, %.15g, %.15g, 0\n" % (k, x, y))
    f.write("*ELEMENT, TYPE=%s, ELSET=EALL\n" % element_type)
    for k, q in enumerate(quads, 1):
        f.write("%d, %s\n" % (k, ", ".join(str(n) for n in q)))
    for name, nodes in nsets:
        f.write("*NSET, NSET=%s\n" % name)
        for k in range(0, len(nodes), 16):
            f.write(", ".join(str(n) for n in nodes[k:k + 16]) + "\n")


def frd_value(frd, inp, block):
    """The first component of node A (the node of the set NA of the .inp) in the last
    `block` (DISP, STRESS, ...) of a CalculiX .frd."""
    with open(inp) as f:
        lines = f.read().splitlines()
    node = int(lines[lines.index("*NSET, NSET=NA") + 1])
    inside, value = False, None
    with open(frd) as f:
        for line in f:
            if line.startswith(" -4"):
                inside = line.split()[1] == block
            elif inside and line.startswith(" -1") and int(line[3:13]) == node:
                value = float(line[13:25])
    if value is None:
        sys.exit("no %s of node %d in %s" % (block, node, frd))
    return value
