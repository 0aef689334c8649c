-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_cyclic_through_list\.lua:7: keyword ELAS\[1\]/NU/E\[1\] is ELAS\[1\] again: a table of keywords cannot contain itself
-- A cycle through a list of occurrences and a deeper table.
local t = {}
local inner = {NU = {E = t}}
t[1] = inner
DEFI_MATERIAU{ELAS = t}
