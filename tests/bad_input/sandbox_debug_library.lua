-- expect-exit: 2
-- expect-output: <F> <LUA> .*sandbox_debug_library\.lua:6: 'debug' is not defined; did you mean DEBUT\?
-- The debug library reaches every upvalue and metatable: debug.getupvalue(load, 1)
-- gave back Lua's own load, which runs bytecode (memory corruption). A
-- sandboxed study has no debug library.
local original = debug.getupvalue(load, 1)
FIN{}
