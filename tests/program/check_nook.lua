-- expect-exit: 1
-- expect-output: NOOK  NON_REGRESSION .*<I> checks: 1 OK, 1 NOOK
-- A deliberately wrong VALE_CALC: the study runs to its end and exits with 1.
F = FORMULE{VALE = 'X**2', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 3, VALE_CALC = 9.0}}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 3, VALE_CALC = 9.1}}
FIN{}
