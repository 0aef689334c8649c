-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_node_not_in_cell\.lua:14: RESU\[1\]: node N3 is not a node of cell M1 \(its nodes: N1, N2, N5, N4\)
-- An ELNO value at a node that is not a node of the cell (N3 is on M2 only).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0},
                    FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, CONTRAINTE = 'SIGM_ELNO'}
TEST_RESU{RESU = {RESULTAT = R, INST = 0.0, NOM_CHAM = 'SIGM_ELNO', MAILLE = 'M1', NOEUD = 'N3', NOM_CMP = 'SIXX', VALE_CALC = 1.0}}
FIN{}
