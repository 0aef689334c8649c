-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*singular_no_dy\.lua:13: UMFPACK: the matrix is numerically singular: .* the structure may be free to move \(missing Dirichlet conditions\?\) or the matrix is very ill conditioned \(unknown DY of node N5\). 1 instant\(s\) were stored before the failure
-- Not enough Dirichlet conditions: DY is free, the message names the free unknown.
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
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
