-- expect-exit: 2
-- expect-output: <F> <AFFE_MODELE> .*kw_missing_mandatory\.lua:7: keyword MAILLAGE is mandatory and missing \(expected a maillage_sdaster\)
-- A mandatory keyword missing.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
FIN{}
