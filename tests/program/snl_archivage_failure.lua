-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE>.*below SUBD_PAS_MINI.*; 2 instant\(s\) were stored before the failure
-- ARCHIVAGE when a later instant fails: with PAS_ARCH = 10 only the initial state and the
-- last instant would be stored; the instants 0.001 and 0.002 of the stiffening bar of
-- snl_driver_options.lua converge, the instant 1 does not (ITER_GLOB_MAXI = 3, and
-- SUBD_PAS_MINI forbids its cutting): the last converged one, 0.002, is stored besides
-- the initial state, as code_aster does: 2 instants.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = 10.0}}
RAMP = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
LI = DEFI_LIST_INST{DEFI_LIST = {VALE = {0.0, 0.001, 0.002, 1.0}}, ECHEC = {SUBD_PAS = 5, SUBD_PAS_MINI = 0.2}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = RAMP}},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, INCREMENT = {LIST_INST = LI},
                  CONVERGENCE = {ITER_GLOB_MAXI = 3}, ARCHIVAGE = {PAS_ARCH = 10}}
