-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*defi_materiau_elas_and_hyper\.lua:5: .*EXCLUS.*ELAS.*ELAS_HYPER
-- ELAS and ELAS_HYPER exclude each other, as in code_aster.
DEBUT{}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, ELAS_HYPER = {C10 = 1.0, K = 100.0}}
FIN{}
