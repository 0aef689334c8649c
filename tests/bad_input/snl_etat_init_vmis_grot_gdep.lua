-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_etat_init_vmis_grot_gdep\.lua:16: ETAT_INIT: EVOL_NOLI's SIEF_ELGA holds Cauchy stresses, and a von Mises law in DEFORMATION='GROT_GDEP' \(cell M1\) integrates from the second Piola-Kirchhoff stress: restarting it from stresses and internal variables is not available
-- A von Mises law in GROT_GDEP keeps S; SIEF_ELGA is Cauchy's: the restart is refused by name.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 100.0, SY = 1.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}, {GROUP_MA = 'HAUT', DY = 1e-4}}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0, 2.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1, INST_FIN = 1.0},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', DEFORMATION = 'GROT_GDEP'}}


R = STAT_NON_LINE{reuse = R, MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', DEFORMATION = 'GROT_GDEP'}, ETAT_INIT = {EVOL_NOLI = R}}
FIN{}
