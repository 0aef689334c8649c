-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*defi_fichier_liberer_by_file\.lua:10: UNITE=30: the file .*defi_fichier_liberer_by_file\.mail does not exist
-- ACTION='LIBERER' by FICHIER releases the unit bound to that file (here under
-- another spelling of its path): the mesh is then looked for at the unit's
-- default place, the study's name with .mail, which does not exist.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 30, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 30}
DEFI_FICHIER{ACTION = 'LIBERER', FICHIER = './../bad_input/base.mail'}
MA2 = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 30}
FIN{}
