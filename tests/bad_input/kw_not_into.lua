-- expect-exit: 2
-- expect-output: <F> <AFFE_MODELE> .*kw_not_into\.lua:7: AFFE\[1\]: keyword MODELISATION = '3D' is not allowed. allowed values: 'D_PLAN', 'C_PLAN'
-- A value outside `into`.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = '3D'}}
FIN{}
