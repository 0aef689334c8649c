-- expect-exit: 2
-- expect-output: <F> <LUA> .*lua_syntax_error\.lua:6: '\}' expected \(to close '\{' at line 5\) near 'FIN'
-- A Lua syntax error.
DEBUT{}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}
FIN{}
