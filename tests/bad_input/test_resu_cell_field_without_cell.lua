-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_cell_field_without_cell\.lua:13: RESU\[1\]: NOEUD designates a node of a field at the nodes of cells \(ELNO\); SIEF_ELGA is at Gauss points: give GROUP_MA and POINT
-- A field on cells checked at a node alone, without its cell.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0},
                    FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
TEST_RESU{RESU = {RESULTAT = R, INST = 0.0, NOM_CHAM = 'SIEF_ELGA', NOEUD = 'N1', NOM_CMP = 'SIXX', VALE_CALC = 1.0}}
FIN{}
