-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_visc_druc_prag_c_plan\.lua:12: RELATION='VISC_DRUC_PRAG', material MAT1 \(cell M1\): VISC_DRUC_PRAG is not available in plane stress \(C_PLAN\): code_aster has it in 3D, AXIS and D_PLAN
-- code_aster has no plane stress version of VISC_DRUC_PRAG: C_PLAN is refused by name.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, VISC_DRUC_PRAG = {PREF = 1.0, A = 1e-3, N = 2.0, P_PIC = 0.01, P_ULT = 0.02, ALPHA_0 = 0.1, ALPHA_PIC = 0.2, ALPHA_ULT = 0.1, R_0 = 1.0, R_PIC = 2.0, R_ULT = 1.0, BETA_0 = 0.0, BETA_PIC = 0.1, BETA_ULT = 0.1}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'VISC_DRUC_PRAG'}}
FIN{}
