-- A study that runs to its end without any check: NO_TEST_RESU for tools/astest.
F = FORMULE{VALE = '2*X', NOM_PARA = {'X'}}
