-- expect-exit: 2
-- expect-output: <F> <DEFI_FICHIER> .*defi_fichier_liberer_unknown_unit\.lua:5: UNITE=31: no file is bound to unit 31, nothing to release \(no unit is bound\)
-- ACTION='LIBERER' of a unit no file is bound to.
DEBUT{}
DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 31}
FIN{}
