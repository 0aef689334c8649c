-- expect-exit: 2
-- expect-output: <I> checks: 1 OK, 0 NOOK.*<F> <LUA> .*os_exit_failure\.lua:7: the study called os\.exit\(3\): it ends as a failure
-- os.exit with a failure code ends the study as a fatal error (exit status 2),
-- after the plots and the summary of the checks; pcall does not catch it.
F = FORMULE{VALE = 'X', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 2.0, VALE_CALC = 2.0}}
pcall(os.exit, 3)
error('not reached')
