-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*option_u_missing_file\.lua:6: UNITE=20: the file .*no_such_file\.mail does not exist \(bind a file with DEFI_FICHIER\{ACTION='ASSOCIER', UNITE=20, FICHIER='\.\.\.'\} or aster-lite -u 20=PATH\)
-- args: -u 20=@DIR@/no_such_file.mail --output-dir @OUT@
-- -u binds unit 20 to a file that does not exist.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
