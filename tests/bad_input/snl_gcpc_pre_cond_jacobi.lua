-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_gcpc_pre_cond_jacobi\.lua:14: SOLVEUR: keyword PRE_COND = 'JACOBI' is not allowed; allowed values: 'LDLT_INC', 'LDLT_SP', 'LDLT_DP'
-- PRE_COND='JACOBI' is one of code_aster's PETSC preconditioners, not GCPC's: the catalogue
-- refuses it by name (LDLT_INC, GCPC's own in code_aster, by snl_gcpc_ldlt_inc.lua).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FX = 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
  SOLVEUR = {METHODE = 'GCPC', PRE_COND = 'JACOBI'}, COMPORTEMENT = {RELATION = 'ELAS'},
  INCREMENT = {LIST_INST = L}}
FIN{}
