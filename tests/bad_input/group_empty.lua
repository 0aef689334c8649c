-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*group_empty\.lua:11: FORCE_CONTOUR\[1\]: group 'VIDE' is empty \(no cell\): the keyword would apply to nothing
-- An empty group in the mesh, used for a load.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'group_empty.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'VIDE', FY = -1.0}}
FIN{}
