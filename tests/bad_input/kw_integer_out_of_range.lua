-- expect-exit: 2
-- expect-output: <F> <DEFI_LIST_REEL> .*kw_integer_out_of_range\.lua:5: INTERVALLE\[1\]: keyword NOMBRE = 4294967298 is out of the range of integers \(-2147483648 to 2147483647\)
-- An integer the operators would truncate to a C++ int (4294967298 ran 2 steps).
DEBUT{}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 4294967298}}
