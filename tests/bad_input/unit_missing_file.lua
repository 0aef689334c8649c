-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*unit_missing_file\.lua:6: UNITE=21: the file .*no_such_mesh\.mail does not exist \(bind a file with DEFI_FICHIER\{ACTION='ASSOCIER', UNITE=21, FICHIER='\.\.\.'\} or aster-lite -u 21=PATH\)
-- A unit bound to a file that does not exist.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 21, FICHIER = 'no_such_mesh.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 21}
FIN{}
