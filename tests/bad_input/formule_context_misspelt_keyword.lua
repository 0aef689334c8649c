-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_context_misspelt_keyword\.lua:5: keyword NOM_PAR is not one of FORMULE's own keywords, so it is a value passed to the expression \(CONTEXTE\): it must be a real, a fonction_sdaster or a formule, got 'X'. did you mean NOM_PARA\?
-- A misspelt keyword of FORMULE is taken for a context value; the message still suggests the keyword.
DEBUT{}
F = FORMULE{VALE = 'X', NOM_PAR = 'X'}
FIN{}
