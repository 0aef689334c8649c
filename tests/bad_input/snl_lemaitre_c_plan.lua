-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_lemaitre_c_plan\.lua:12: RELATION='LEMAITRE', material MAT1 \(cell M1\): LEMAITRE is not available in C_PLAN \(code_aster has it in 3D, D_PLAN and AXIS\)
-- code_aster has no plane stress LEMAITRE.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, LEMAITRE = {N = 3.0, UN_SUR_K = 0.01}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'LEMAITRE'}}
FIN{}
