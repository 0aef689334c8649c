-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*newton_diverges\.lua:13: the instant 1\.000000E\+00 did not converge: no convergence in ITER_GLOB_MAXI = 5 Newton iterations \(RESI_GLOB_RELA = [0-9.E+-]+\) \(even after cutting the step 3 times\). 1 instant\(s\) were stored before the failure
-- A Newton that cannot converge: the steps are cut, then the instant is named.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0e6}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
  INCREMENT = {LIST_INST = L},
  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GREEN_LAGRANGE'}, CONVERGENCE = {ITER_GLOB_MAXI = 5}}
FIN{}
