-- expect-exit: 2
-- expect-output: <F> <LUA> .*sandbox_concept_metatable\.lua:6: attempt to call a nil value \(field '__gc'\)
-- getmetatable gives a study the name of a concept's metatable, not its
-- metamethods: __gc called by hand on a number was a SIGSEGV.
F = FORMULE{VALE = 'X', NOM_PARA = 'X'}
getmetatable(F).__gc(42)
FIN{}
