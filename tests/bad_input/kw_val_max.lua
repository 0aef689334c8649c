-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_val_max\.lua:5: ELAS: keyword NU = 0\.7 is above its maximum 0\.5
-- A value above val_max (NU >= 0.5).
DEBUT{}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.7}}
FIN{}
