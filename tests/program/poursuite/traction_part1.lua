-- Part 1 of a study split in two files (traction_part2.lua continues it, POURSUITE):
-- the rectangle [0, 4] x [0, 1] (four QUAD4, ../rectangle_4x1.mail on unit 20, bound by
-- the command line or the .export), D_PLAN, E = 100, NU = 0.3, DX = 0 on the left
-- nodes, DY = 0 at P1 (0, 0), a traction SX = 2 on DROITE. FIN ends this file only.
DEBUT{CODE = {NIV_PUB_WEB = 'INTERNET'}, PAR_LOT = 'NON'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 100.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_NO = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = 2.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR}}}
FIN{}
