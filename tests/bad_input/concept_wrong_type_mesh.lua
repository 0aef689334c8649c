-- expect-exit: 2
-- expect-output: <F> <AFFE_MATERIAU> .*concept_wrong_type_mesh\.lua:11: keyword MAILLAGE expects a maillage_sdaster, got a modele_sdaster
-- A model where a mesh is expected.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
CM2 = AFFE_MATERIAU{MAILLAGE = MO, AFFE = {TOUT = 'OUI', MATER = MAT}}
FIN{}
