-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*formule_ddl_impo_sqrt\.lua:13: DDL_IMPO DX on node N1 at X = 0, Y = 0, INST = 0\.5: sqrt of a negative number \(sqrt\(-0\.5\)\) at column 1 of "sqrt\(Y - 0\.5\)", with X = 0, Y = 0. 1 instant\(s\) were stored before the failure
-- DDL_IMPO with a FORMULE that takes the square root of a negative number.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
UX = FORMULE{VALE = 'sqrt(Y - 0.5)', NOM_PARA = {'X', 'Y'}}
BC = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = UX, DY = UX}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}},
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
