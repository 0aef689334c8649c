-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_unary_minus_chain\.lua:4: VALE: expression nested too deeply at column 201
-- A million unary minus signs.
F = FORMULE{VALE = string.rep('-', 1000000) .. 'X', NOM_PARA = {'X'}}
