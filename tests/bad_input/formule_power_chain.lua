-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_power_chain\.lua:5: VALE: expression nested too deeply at column 602 \(more than 200 levels of parentheses, calls, signs and powers\)
-- 100 000 chained powers (right-associative: each one a level of the parser's
-- recursion, which overflowed the C++ stack).
F = FORMULE{VALE = 'X' .. string.rep('**X', 100000), NOM_PARA = {'X'}}
