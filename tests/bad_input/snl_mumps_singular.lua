-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_mumps_singular\.lua:14: MUMPS: the matrix is numerically singular: 1 null pivot\(s\), the first in column [0-9]+ \(its row fell below 1e-8 times the matrix's norm, NPREC = 8\); the structure may be free to move \(missing Dirichlet conditions\?\) \(unknown DY of node N[0-9]+\); 1 instant\(s\) were stored before the failure
-- SOLVEUR METHODE = 'MUMPS': not enough Dirichlet conditions, DY is free; MUMPS's null pivot
-- detection finds it, the message names the free unknown as the other solvers do.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FX = 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
  SOLVEUR = {METHODE = 'MUMPS'}, COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
