-- expect-exit: 2
-- expect-output: <F> <DEFI_FICHIER> .*defi_fichier_liberer_nothing\.lua:5: exactly one of UNITE, FICHIER is required, got none \(rule UN_PARMI\('UNITE', 'FICHIER'\)\)
-- ACTION='LIBERER' without UNITE or FICHIER: which unit to release?
DEBUT{}
DEFI_FICHIER{ACTION = 'LIBERER'}
FIN{}
