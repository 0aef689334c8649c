-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*defi_materiau_hyper_k_and_nu\.lua:5: .*UN_PARMI.*K.*NU
-- ELAS_HYPER takes its compressibility as K or as NU, not both.
DEBUT{}
MAT1 = DEFI_MATERIAU{ELAS_HYPER = {C10 = 1.0, K = 100.0, NU = 0.3}}
FIN{}
