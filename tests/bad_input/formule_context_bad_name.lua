-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_context_bad_name\.lua:5: keyword '2A' is not a valid name: a value passed to the expression \(CONTEXTE\) is named by a letter or _ then letters, digits or _
-- A FORMULE given a context value under a name the expression cannot use.
DEBUT{}
F = FORMULE{VALE = 'X', ['2A'] = 2.0, NOM_PARA = 'X'}
FIN{}
