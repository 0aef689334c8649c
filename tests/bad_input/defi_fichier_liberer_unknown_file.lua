-- expect-exit: 2
-- expect-output: <F> <DEFI_FICHIER> .*defi_fichier_liberer_unknown_file\.lua:7: FICHIER='autre\.mail': no unit is bound to .*bad_input/autre\.mail, nothing to release \(bound units: 30 -> .*base\.mail\)
-- ACTION='LIBERER' of a file no unit is bound to.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 30, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 30}
DEFI_FICHIER{ACTION = 'LIBERER', FICHIER = 'autre.mail'}
FIN{}
