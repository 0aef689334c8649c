-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_cell_without_node\.lua:13: RESU\[1\]: MAILLE M1 does not hold the node N3 of this nodal field
-- MAILLE beside NOEUD on a nodal field (DEPL) is accepted only when the cell holds the node.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0},
                    FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
TEST_RESU{RESU = {RESULTAT = R, INST = 0.0, NOM_CHAM = 'DEPL', MAILLE = 'M1', NOEUD = 'N3', NOM_CMP = 'DX', VALE_CALC = 1.0}}
FIN{}
