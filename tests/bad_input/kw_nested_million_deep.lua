-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_nested_million_deep\.lua:6: keyword ELAS(/E)+ is nested 20 tables deep
-- Keyword tables nested a million deep.
local t = {E = 1.0}
for _ = 1, 1000000 do t = {E = t} end
DEFI_MATERIAU{ELAS = t}
