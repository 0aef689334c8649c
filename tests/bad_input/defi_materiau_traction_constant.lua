-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*defi_materiau_traction_constant\.lua:6: TRACTION/SIGM: C is a constant function; the traction curve is a function of EPSI given by points
-- TRACTION's SIGM must be a curve of EPSI, not a constant.
DEBUT{}
C = DEFI_CONSTANTE{VALE = 200.0}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, TRACTION = {SIGM = C}}
FIN{}
