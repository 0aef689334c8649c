-- expect-exit: 2
-- expect-output: <F> <DEFI_FONCTION> .*fonction_odd_vale\.lua:5: VALE holds pairs \(x1, y1, x2, y2, \.\.\.\): got an odd count, 3
-- DEFI_FONCTION with an odd number of values in VALE.
DEBUT{}
F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0}}
FIN{}
