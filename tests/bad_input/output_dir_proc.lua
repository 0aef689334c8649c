-- expect-exit: 2
-- expect-output: <F> <TEST_FONCTION> .*output_dir_proc\.lua:7: cannot create the output folder /proc/forbidden/out: No such file or directory
-- args: --output-dir /proc/forbidden/out
-- An output folder that cannot be created.
DEBUT{}
F = FORMULE{VALE = 'X', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 0.5, VALE_CALC = 0.5}}
FIN{}
