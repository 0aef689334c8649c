#!/usr/bin/env python3
"""Writes the thick cylinder in creep for aster-lite (.mail) and CalculiX (.inp).

The mesh of thick_cylinder.py (a quarter of a long thick cylinder, a = 1, b = 2,
plane strain, NT x NR QUAD8 cells, about 6 NT NR unknowns: NT = NR = 256 is 0.4 M),
elastic (E = 210000, NU = 0.3) with Norton creep
  d eps_v / dt = 3/2 (s_eq / K)^N s / s_eq,   N = 4, 1/K = 3e-4,
under an internal pressure P = 100 applied at the first instant and held to T = 1000,
in 20 equal increments integrated by the implicit Euler scheme. CalculiX's
*CREEP, LAW=NORTON is eps_eq' = A q^n t^m: A = (1/K)^N, n = N, m = 0; its *VISCO
step takes the same 20 increments (DIRECT) with the pressure constant over the step
(an amplitude of 1 from the step's start). The bore's creep strain at T is about
three times its elastic strain.

usage: thick_cylinder_creep.py NT NR OUTPUT.mail OUTPUT.inp
       thick_cylinder_creep.py --frd-ux RESULTS.frd OUTPUT.inp
         (prints the radial displacement of node A, (a, 0), in the last step of a .frd)
"""
import sys

from quad8_files import frd_value
from thick_cylinder import write_mesh

E, NU = 210000.0, 0.3
N, UN_SUR_K = 4.0, 3e-4
PRESSURE = 100.0
DURATION, INCREMENTS = 1000.0, 20


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "--frd-ux":
        print("%.7g" % frd_value(sys.argv[2], sys.argv[3], "DISP"))
        return
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    nt, nr = int(sys.argv[1]), int(sys.argv[2])
    with open(sys.argv[4], "w") as f:
        write_mesh(nt, nr, sys.argv[3], f, "Thick cylinder in Norton creep, quarter model, NT=%d NR=%d, CPE8" % (nt, nr))
        f.write("*MATERIAL, NAME=STEEL\n*ELASTIC\n%g, %g\n" % (E, NU))
        f.write("*CREEP, LAW=NORTON\n%.15g, %g, 0.0\n" % (UN_SUR_K ** N, N))
        f.write("*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n0.01\n")
        f.write("*BOUNDARY\nNBAS, 2, 2, 0.0\nNGAUCHE, 1, 1, 0.0\n")
        # The pressure from the first increment on, as aster-lite's load without a ramp.
        f.write("*AMPLITUDE, NAME=HELD\n0.0, 1.0, %g, 1.0\n" % DURATION)
        # The same 20 increments as aster-lite, none cut or added.
        f.write("*STEP, INC=1000\n*VISCO, DIRECT, CETOL=1.0\n%.15g, %g\n*DLOAD, AMPLITUDE=HELD\n" % (DURATION / INCREMENTS, DURATION))
        for c in range(nt):  # face 4 (nodes 4-1) of the first row of cells
            f.write("%d, P4, %.15g\n" % (c + 1, PRESSURE))
        f.write("*NODE PRINT, NSET=NA\nU\n*NODE FILE\nU\n*END STEP\n")


if __name__ == "__main__":
    main()
