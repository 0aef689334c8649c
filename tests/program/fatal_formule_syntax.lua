-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*fatal_formule_syntax.lua:4: VALE: unexpected '\)' at column 6 \(no '\(' to close\)
-- A fatal error after a check: exit 2 even though the check was OK.
F = FORMULE{VALE = 'X + 1)', NOM_PARA = 'X'}
