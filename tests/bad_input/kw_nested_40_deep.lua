-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_nested_40_deep\.lua:7: keyword ELAS(/E)+ is nested 20 tables deep. a command's keywords are at most 3 deep
-- Keyword tables nested 40 deep: the depth limit, not a crash (the Lua stack
-- overflowed while the tree was read).
local t = {E = 1.0}
for _ = 1, 40 do t = {E = t} end
DEFI_MATERIAU{ELAS = t}
