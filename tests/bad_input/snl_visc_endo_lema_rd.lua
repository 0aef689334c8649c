-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_visc_endo_lema_rd\.lua:12: RELATION='VISC_ENDO_LEMA', material MAT1 \(cell M1\): VISC_ENDO_LEMA: VISC_ENDO's R_D must be > 0 \(the damage rate grows with the stress\), got -1
-- A damage rate that would fall as the stress grows (R_D <= 0) is refused, naming the keyword.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, LEMAITRE = {N = 4.0, UN_SUR_K = 0.01}, VISC_ENDO = {R_D = -1.0, A_D = 100.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'VISC_ENDO_LEMA'}}
FIN{}
