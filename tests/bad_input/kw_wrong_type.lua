-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_wrong_type\.lua:5: ELAS: keyword E expects a real, got 'steel'
-- A text where a real is expected.
DEBUT{}
MAT = DEFI_MATERIAU{ELAS = {E = 'steel', NU = 0.3}}
FIN{}
