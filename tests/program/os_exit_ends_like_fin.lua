-- expect-exit: 1
-- expect-output: NOOK  NON_REGRESSION.*<I> checks: 1 OK, 1 NOOK
-- os.exit() ends the study as FIN does, pcall or not: the summary of the checks
-- is printed and the exit status is theirs (1: a check is NOOK).
F = FORMULE{VALE = 'X**2', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 3, VALE_CALC = 9.0}}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 3, VALE_CALC = 9.1}}
pcall(os.exit)
error('not reached')
