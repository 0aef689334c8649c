-- expect-exit: 0
-- expect-output: <I> checks: 1 OK, 0 NOOK
-- Nothing after FIN runs, even when FIN is called through pcall.
F = FORMULE{VALE = 'X**2', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 3, VALE_CALC = 9.0}}
pcall(FIN)
error('not reached')
