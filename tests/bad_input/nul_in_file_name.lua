-- expect-exit: 2
-- expect-output: <F> <DEFI_FICHIER> .*nul_in_file_name\.lua:6: keyword FICHIER = 'base\.mail\\0\.bak' contains a NUL byte \('\\0'\)
-- A NUL byte in a file name: the name was cut there silently (base.mail was read).
DEBUT{}
-- 'base.mail\0.bak'
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail\0.bak'}
