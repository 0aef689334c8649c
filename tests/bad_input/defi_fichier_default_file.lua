-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*defi_fichier_default_file\.lua:7: UNITE=30: the file .*bad_input/fort\.30 does not exist
-- ASSOCIER without FICHIER binds fort.<UNITE> in the study's folder, as the
-- catalogue says; there is no such file here.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 30}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 30}
FIN{}
