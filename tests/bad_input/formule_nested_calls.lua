-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_nested_calls\.lua:4: VALE: expression nested too deeply at column 804
-- 100 000 nested function calls (parentheses were bounded, calls were not).
F = FORMULE{VALE = string.rep('sin(', 100000) .. 'X' .. string.rep(')', 100000),
            NOM_PARA = {'X'}}
