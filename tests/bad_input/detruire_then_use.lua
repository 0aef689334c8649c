-- expect-exit: 2
-- expect-output: <F> <LUA> .*detruire_then_use\.lua:13: 'MA' was destroyed by DETRUIRE at .*detruire_then_use\.lua:10
-- A mesh used after DETRUIRE destroyed it. The model built on it keeps it
-- internally and stays usable (AFFE_CHAR_MECA on MO); the name MA does not.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
DETRUIRE{CONCEPT = {NOM = MA}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_NO = 'COIN', DX = 0.0}}
assert(BC)
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
FIN{}
