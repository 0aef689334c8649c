-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*fonc_mult_divide_by_zero\.lua:15: FONC_MULT at INST = 0\.5: division by zero \(0\.5 / 0\) at column 6 of "INST / \(INST - 0\.5\)", with INST = 0\.5. 1 instant\(s\) were stored before the failure
-- A FONC_MULT that is infinite at INST = 0.5 (the run said the residual was not
-- a number, even after cutting the step).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
RAMPE = FORMULE{VALE = 'INST / (INST - 0.5)', NOM_PARA = {'INST'}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F, FONC_MULT = RAMPE}},
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
