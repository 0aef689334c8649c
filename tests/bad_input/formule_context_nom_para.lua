-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_context_nom_para\.lua:5: keyword X names both a parameter \(NOM_PARA\) and a value passed to the expression
-- A FORMULE whose context value has the name of one of its parameters.
DEBUT{}
F = FORMULE{VALE = 'A*X', A = 2.0, X = 3.0, NOM_PARA = 'X'}
FIN{}
