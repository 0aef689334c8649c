-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*defi_materiau_traction_not_epsi\.lua:6: TRACTION/SIGM: F is a function of INST; the traction curve is a function of EPSI
-- TRACTION's SIGM is a function of EPSI (code_aster checks the parameter).
DEBUT{}
F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.001, 1.0, 0.01, 2.0}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, TRACTION = {SIGM = F}}
FIN{}
