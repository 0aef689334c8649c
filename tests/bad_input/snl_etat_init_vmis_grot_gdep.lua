-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_etat_init_vmis_grot_gdep\.lua:16: ETAT_INIT: the stresses \(SIEF_ELGA, Cauchy's\) of cell M1 would be converted to the second Piola-Kirchhoff stress its law in DEFORMATION='GROT_GDEP' or 'GDEF_LOG' integrates from, and in C_PLAN the out-of-plane stretch this needs is not known from the displacements: restarting such a law in C_PLAN from stresses is not available \(D_PLAN and AXIS are\)
-- A von Mises law in GROT_GDEP keeps S; SIEF_ELGA is Cauchy's: the restart converts it with F,
-- whose out-of-plane stretch in C_PLAN only the law knows: refused there by name.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 100.0, SY = 1.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}, {GROUP_MA = 'HAUT', DY = 1e-4}}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0, 2.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1, INST_FIN = 1.0},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', DEFORMATION = 'GROT_GDEP'}}

R = STAT_NON_LINE{reuse = R, MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', DEFORMATION = 'GROT_GDEP'}, ETAT_INIT = {EVOL_NOLI = R}}
FIN{}
