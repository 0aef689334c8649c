-- expect-exit: 2
-- expect-output: <F> <DEFI_LIST_INST> .*list_inst_pas_mini\.lua:5: .*PAS_MINI
-- PAS_MINI is not implemented: refused, not ignored.
DEBUT{}
L = DEFI_LIST_INST{DEFI_LIST = {VALE = {0.0, 0.5, 1.0}, PAS_MINI = 1.0E-3}}
