-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*formule_divide_by_zero\.lua:14: FORCE_CONTOUR FY on cell M3 at X = 0\.1127016653792583, Y = 1, INST = 0\.5: division by zero \(-1 / 0\) at column 6 of "-1\.0 / \(INST - 0\.5\)", with X = 0\.1127016653792583, INST = 0\.5. 1 instant\(s\) were stored before the failure
-- FORCE_CONTOUR with a FORMULE that divides by zero at INST = 0.5.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
FY = FORMULE{VALE = '-1.0 / (INST - 0.5)', NOM_PARA = {'X', 'INST'}}
F = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = FY}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
