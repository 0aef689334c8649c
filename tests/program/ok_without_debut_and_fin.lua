-- expect-exit: 0
-- expect-output: <I> checks: 1 OK, 0 NOOK
-- DEBUT and FIN may be omitted: the study ends with its last command.
F = FORMULE{VALE = '2*X', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 1.5, VALE_CALC = 3.0}}
