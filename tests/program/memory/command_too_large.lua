-- expect-exit: 2
-- expect-output: <F> <DEFI_LIST_REEL> .*command_too_large\.lua:5: not enough memory \(the command asks for more than the system gives it\)
-- Run under prlimit --as: a command whose result does not fit (2e9 instants,
-- 16 GB) ends with std::bad_alloc, reported as such (it said "internal error").
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2000000000}}
