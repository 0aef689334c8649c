-- expect-exit: 2
-- expect-output: <F> <LUA> .*fatal_lua_error.lua:4: boom
DEBUT{}
error('boom')
