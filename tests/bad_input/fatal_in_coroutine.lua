-- expect-exit: 2
-- expect-output: <F> <DEFI_LIST_REEL> .*fatal_in_coroutine\.lua:6: INTERVALLE 1: JUSQU_A = 0 must be greater than 1.*<F> <LUA> the study went on after 1 fatal error \(caught with pcall or in a coroutine\)
-- A <F> inside a coroutine: coroutine.resume returns it, the run still ends
-- with exit status 2 and the message.
local co = coroutine.create(function()
  L = DEFI_LIST_REEL{DEBUT = 1.0, INTERVALLE = {JUSQU_A = 0.0, NOMBRE = 2}}
end)
assert(not coroutine.resume(co))
FIN{}
