-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_suiv_not_pressure\.lua:14: EXCIT\[2\]: TYPE_CHARGE='SUIV' applies to PRES_REP only, and the load F holds FORCE_NODALE: give it in a load of its own with FIXE_CSTE
-- TYPE_CHARGE = 'SUIV' (follower load) on a load that holds a nodal force: only
-- a pressure follows the deformation, as in code_aster.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = 'COIN', FX = 1.0}, PRES_REP = {GROUP_MA = 'BAS', PRES = 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F, TYPE_CHARGE = 'SUIV'}},
  COMPORTEMENT = {DEFORMATION = 'GROT_GDEP'}, INCREMENT = {LIST_INST = L}}
FIN{}
