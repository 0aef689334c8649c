-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*concept_wrong_type_charge\.lua:12: EXCIT\[2\]: keyword CHARGE expects a char_meca or a char_cine_meca, got a mater_sdaster
-- A material where a load is expected.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = MAT}},
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
