-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*unit_default_missing\.lua:5: UNITE=20: the file .*unit_default_missing\.mail does not exist \(bind a file with DEFI_FICHIER\{ACTION='ASSOCIER', UNITE=20, FICHIER='\.\.\.'\} or aster-lite -u 20=PATH\)
-- No file for the default unit 20 (the study name with .mail).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER'}
FIN{}
