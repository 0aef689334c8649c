-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_context_text\.lua:5: keyword A is not one of FORMULE's own keywords, so it is a value passed to the expression \(CONTEXTE\): it must be a real, a fonction_sdaster or a formule, got 'two'
-- A FORMULE given a text as a context value: only numbers and functions are.
DEBUT{}
F = FORMULE{VALE = 'A*X', A = 'two', NOM_PARA = 'X'}
FIN{}
