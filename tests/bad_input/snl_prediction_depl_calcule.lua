-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_prediction_depl_calcule\.lua:13: NEWTON: keyword PREDICTION = 'DEPL_CALCULE' is not allowed. allowed values: 'TANGENTE', 'ELASTIQUE', 'EXTRAPOLE'
-- NEWTON/PREDICTION = 'DEPL_CALCULE' (a prediction from a given displacement
-- field) is not implemented: the catalogue refuses it and lists what is.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}}, NEWTON = {PREDICTION = 'DEPL_CALCULE'},
  INCREMENT = {LIST_INST = L}}
FIN{}
