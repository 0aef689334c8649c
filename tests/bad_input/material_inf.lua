-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*material_inf\.lua:5: ELAS: keyword E = inf is not a finite number \(0/0, 1/0 or math\.huge in the study\?\)
-- 1/0 as Young's modulus.
DEBUT{}
MAT = DEFI_MATERIAU{ELAS = {E = 1/0, NU = 0.3}}
