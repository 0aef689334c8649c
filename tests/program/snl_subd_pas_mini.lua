-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE>.*would make a sub-step of 1.000E-01, below SUBD_PAS_MINI = 2.000E-01
-- DEFI_LIST_INST/ECHEC/SUBD_PAS_MINI: the step that fails (the stiffening bar of
-- snl_driver_options.lua with ITER_GLOB_MAXI = 3) would be cut into SUBD_PAS = 5
-- sub-steps of 0.1, shorter than SUBD_PAS_MINI = 0.2: the computation stops and says so.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = 10.0}}
RAMP = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
LI = DEFI_LIST_INST{DEFI_LIST = {VALE = {0.0, 0.5, 1.0}}, ECHEC = {SUBD_PAS = 5, SUBD_PAS_MINI = 0.2}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = RAMP}},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, INCREMENT = {LIST_INST = LI},
                  CONVERGENCE = {ITER_GLOB_MAXI = 3}}
