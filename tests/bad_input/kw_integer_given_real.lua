-- expect-exit: 2
-- expect-output: <F> <DEFI_LIST_REEL> .*kw_integer_given_real\.lua:5: INTERVALLE\[1\]: keyword NOMBRE expects an integer, got 2\.5
-- A real where an integer is expected.
DEBUT{}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2.5}}
