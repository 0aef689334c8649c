-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_gma_on_nodal_field\.lua:14: RESU\[1\]: GROUP_MA designates a cell or a point of a field on cells; NOM_CHAM='DEPL' is a nodal field: give NOEUD or GROUP_NO
-- GROUP_MA and POINT on a nodal field (DEPL).
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
TEST_RESU{RESU = {RESULTAT = R, INST = 0.0, NOM_CHAM = 'DEPL', GROUP_MA = 'C1', POINT = 1, NOM_CMP = 'DX', VALE_CALC = 1.0}}
FIN{}
