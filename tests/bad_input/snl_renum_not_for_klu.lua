-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_renum_not_for_klu\.lua:13: SOLVEUR: keyword RENUM = 'METIS' is not allowed. allowed values: 'AUTO', 'AMD', 'COLAMD', 'SANS'
-- SOLVEUR/RENUM: each METHODE takes the orderings it honours (KLU has no METIS);
-- another is refused by the catalogue, never silently ignored.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}}, SOLVEUR = {METHODE = 'KLU', RENUM = 'METIS'},
  INCREMENT = {LIST_INST = L}}
FIN{}
