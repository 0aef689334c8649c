-- expect-exit: 2
-- expect-output: <F> <MECA_STATIQUE> .*meca_statique_fonc_mult_fails_later\.lua:14: FONC_MULT at INST = 0\.75: division by zero .*; 2 instant\(s\) were stored before the failure, in .*R\.pvd
-- A FONC_MULT that is infinite at the third instant: the first two are on disk.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.25, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 3}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
RAMPE = FORMULE{VALE = 'INST / (INST - 0.75)', NOM_PARA = {'INST'}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F, FONC_MULT = RAMPE}},
                  LIST_INST = L}
FIN{}
