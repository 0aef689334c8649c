-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_cyclic_table\.lua:6: keyword ELAS/E is ELAS again: a table of keywords cannot contain itself
-- A keyword table that contains itself (the reading recursed until the stack
-- overflowed).
local t = {}
t.E = t; DEFI_MATERIAU{ELAS = t}
