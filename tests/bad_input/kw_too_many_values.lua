-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_too_many_values\.lua:5: ELAS: keyword E takes at most 1 value, got 2
-- A list where one value is expected.
DEBUT{}
MAT = DEFI_MATERIAU{ELAS = {E = {1000.0, 2000.0}, NU = 0.3}}
FIN{}
