-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_reuse_without_etat_init\.lua:14: reuse=: STAT_NON_LINE continues a result from a state; give ETAT_INIT = \{EVOL_NOLI = R\} \(its last instant, or INST / NUME_ORDRE\)
-- reuse= without ETAT_INIT: the state to continue from is not said (it used to
-- restart from zero displacements while appending to the result).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}}, INCREMENT = {LIST_INST = L, INST_FIN = 0.5}}
R = STAT_NON_LINE{reuse = R, MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}},
  INCREMENT = {LIST_INST = L}}
FIN{}
