-- expect-exit: 2
-- expect-output: <F> <DEFI_LIST_REEL> .*vale_inf_in_list_reel\.lua:5: keyword VALE \(value 3\) = inf is not a finite number
-- math.huge in a list of instants.
DEBUT{}
L = DEFI_LIST_REEL{VALE = {0.0, 0.5, math.huge}}
