-- expect-exit: 2
-- expect-output: <F> <MA:getCells> .*nul_in_method_argument\.lua:7: argument 1 = 'HAUT\\0BAS' contains a NUL byte \('\\0'\)
-- A NUL byte in a method's argument (it gave the cells of HAUT).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
print(#MA:getCells('HAUT\0BAS'))
