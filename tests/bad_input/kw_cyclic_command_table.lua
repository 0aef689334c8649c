-- expect-exit: 2
-- expect-output: <F> <DEFI_MATERIAU> .*kw_cyclic_command_table\.lua:6: keyword ELAS/E is the command's table again: a table of keywords cannot contain itself
-- The command's own table inside one of its keywords.
local call = {}
call.ELAS = {E = call}
DEFI_MATERIAU(call)
