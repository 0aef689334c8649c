-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_gcpc_unsymmetric\.lua:16: GCPC needs a symmetric matrix, but A\(11,10\) = [-0-9.e+]+ and A\(10,11\) = [-0-9.e+]+; GCPC \(conjugate gradient\) solves symmetric positive definite systems only: use a direct solver \(METHODE='MULT_FRONT' or 'MUMPS'\), or NEWTON/MATR_RIGI_SYME='OUI'
-- A follower pressure (TYPE_CHARGE='SUIV') in large strain makes the tangent unsymmetric:
-- GCPC refuses it by name and says what solves it.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU = {GROUP_MA_PEAU = {'HAUT'}}}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
P = AFFE_CHAR_MECA{MODELE = MO, PRES_REP = {GROUP_MA = 'HAUT', PRES = 10.0}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = P, FONC_MULT = RAMPE, TYPE_CHARGE = 'SUIV'}},
  SOLVEUR = {METHODE = 'GCPC'}, COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
  INCREMENT = {LIST_INST = L}}
FIN{}
