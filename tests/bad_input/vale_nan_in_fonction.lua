-- expect-exit: 2
-- expect-output: <F> <DEFI_FONCTION> .*vale_nan_in_fonction\.lua:5: keyword VALE \(value 4\) = nan is not a finite number \(0/0, 1/0 or math\.huge in the study\?\)
-- 0/0 in a function's values: refused where it is given.
DEBUT{}
F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 0/0}}
