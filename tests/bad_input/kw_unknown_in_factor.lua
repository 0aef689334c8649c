-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_unknown_in_factor\.lua:5: ELAS: keyword NUU is not a keyword of ELAS. did you mean NU\? \(allowed: E, NU, RHO, ALPHA\)
-- A misspelt keyword in a factor keyword.
DEBUT{}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NUU = 0.3}}
FIN{}
