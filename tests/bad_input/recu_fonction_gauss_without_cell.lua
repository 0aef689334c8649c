-- expect-exit: 2
-- expect-output: <F> <RECU_FONCTION> .*recu_fonction_gauss_without_cell\.lua:12: SIEF_ELGA is a field at Gauss points: give the cell \(MAILLE or GROUP_MA\) and POINT
-- RECU_FONCTION of a field at Gauss points given a node: the message says what designates a Gauss point.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}, {GROUP_MA = 'HAUT', DY = 0.01}}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
F = RECU_FONCTION{RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', NOM_CMP = 'SIXX', GROUP_NO = 'COIN'}
FIN{}
