-- expect-exit: 2
-- expect-output: <F> <DEFI_LIST_REEL> .*list_reel_decreasing\.lua:5: INTERVALLE 1: JUSQU_A = 0 must be greater than 1
-- DEFI_LIST_REEL that goes backwards.
DEBUT{}
L = DEFI_LIST_REEL{DEBUT = 1.0, INTERVALLE = {JUSQU_A = 0.0, NOMBRE = 2}}
FIN{}
