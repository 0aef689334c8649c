-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*singular_no_dy_stop_singulier\.lua:16: the instant 5\.000000E-01 did not converge: no convergence in ITER_GLOB_MAXI = 10 Newton iterations \(RESI_GLOB_RELA = [0-9.E+]+\) \(even after cutting the step 3 times\); SOLVEUR: NPREC <= 0 or STOP_SINGULIER = 'NON' solves even a singular matrix, whose corrections do not reduce the residual: check the Dirichlet conditions
-- Not enough Dirichlet conditions (DY is free) and a load in Y that nothing
-- balances, with SOLVEUR = {STOP_SINGULIER = 'NON'}: the singular matrix is solved anyway, the
-- correction is garbage (DY of 8E12) and the residual does not fall (RESI_GLOB_RELA
-- 1.36 after it). That passed for convergence (the round-off of 8E12), exit 0.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}}, SOLVEUR = {STOP_SINGULIER = 'NON'},
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
