-- expect-exit: 2
-- expect-output: PRES_REP PRES depends on the current position \(XF, YF, ZF\): apply the load as a follower load, EXCIT TYPE_CHARGE='SUIV'
-- A pressure of XF is known only on the current (deformed) edge: a dead load refuses it.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../program/square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 200.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
PF = FORMULE{VALE = '1 + XF', NOM_PARA = 'XF'}
P = AFFE_CHAR_MECA_F{MODELE = MO, PRES_REP = {GROUP_MA = 'HAUT', PRES = PF}}
L1 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = P}},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, INCREMENT = {LIST_INST = L1}}
