-- expect-exit: 2
-- expect-output: <F> <LUA> .*unsafe_concept_metamethods\.lua:14: the concepts' __tostring was called on a table, not on a concept.*<F> <LUA> .*unsafe_concept_metamethods\.lua:15: the concepts' __index was called on a number, not on a concept.*<F> <LUA> .*unsafe_concept_metamethods\.lua:16: 'x' is not defined.*<F> <LUA> the study went on after 3 fatal errors.*<F> <LUA> .*unsafe_concept_metamethods\.lua:23: the concepts' __call was called on a released concept, not on a concept
-- args: --unsafe-lua --output-dir @OUT@
-- With --unsafe-lua, debug.getmetatable reaches the metamethods of concepts and
-- CO() names: called on the wrong value, twice, or before a use, they give a
-- <F> or do nothing, never a signal (a SIGSEGV and a use after free before).
F = FORMULE{VALE = 'X', NOM_PARA = 'X'}
local meta, co = debug.getmetatable(F), debug.getmetatable(CO('A'))
meta.__gc(42)
meta.__gc({})
co.__gc(42)
co.__gc(F)
assert(not meta.__eq(F, 1) and meta.__eq(F, F))
print(pcall(meta.__tostring, {}))
print(pcall(meta.__index, 1, 'x'))
print(pcall(debug.getmetatable(_G).__index, 42, 'x'))
local name = CO('B')
co.__gc(name)
co.__gc(name)
assert(F(2.0) == 2.0)
meta.__gc(F)
meta.__gc(F)
print(F(2.0))
FIN{}
