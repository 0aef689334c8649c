-- expect-exit: 2
-- expect-output: after pcall.*<F> <DEBUT> .*fatal_caught_by_pcall\.lua:5: keyword PAR_LOT = 'PEUT-ETRE' is not allowed; allowed values: 'OUI', 'NON'.*<F> <LUA> the study went on after 1 fatal error \(caught with pcall or in a coroutine\): a fatal error ends the run with exit status 2
-- A <F> the study catches with pcall is fatal all the same: the study goes on
-- (pcall returns the error), the run ends with the message and exit status 2.
local ok, err = pcall(DEBUT, {PAR_LOT = 'PEUT-ETRE'})
assert(not ok and err.aster_fatal)
print('after pcall')
