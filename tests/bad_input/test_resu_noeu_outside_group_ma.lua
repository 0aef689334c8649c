-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_noeu_outside_group_ma\.lua:15: RESU\[1\]: the field SIGM_NOEU is not defined at node N3
-- SIGM_NOEU computed on the cells of C1 only (M1): N3 is not on them.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0},
                    FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
MA = DEFI_GROUP{reuse = MA, MAILLAGE = MA, CREA_GROUP_MA = {NOM = 'C1', MAILLE = 'M1'}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, GROUP_MA = 'C1', CONTRAINTE = 'SIGM_NOEU'}
TEST_RESU{RESU = {RESULTAT = R, INST = 0.0, NOM_CHAM = 'SIGM_NOEU', NOEUD = 'N3', NOM_CMP = 'SIXX', VALE_CALC = 1.0}}
FIN{}
