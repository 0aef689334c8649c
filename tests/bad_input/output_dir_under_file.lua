-- expect-exit: 2
-- expect-output: <F> <TEST_FONCTION> .*output_dir_under_file\.lua:7: cannot create the output folder .*base\.mail/out: Not a directory
-- args: --output-dir @DIR@/base.mail/out
-- An output folder under a regular file.
DEBUT{}
F = FORMULE{VALE = 'X', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 0.5, VALE_CALC = 0.5}}
FIN{}
