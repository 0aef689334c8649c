-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_iter_inte_pas\.lua:13: COMPORTEMENT: ITER_INTE_PAS=4: the imposed local subdivision of the step is not available \(only ITER_INTE_PAS <= 1\)
-- The imposed local subdivision of the step at a Gauss point (ITER_INTE_PAS > 1) is refused by name;
-- negative values (a subdivision only where the local integration fails) are accepted.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 100.0, SY = 1.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', ITER_INTE_PAS = 4}}
FIN{}
