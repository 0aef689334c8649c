-- expect-exit: 2
-- expect-output: <F> <DEFI_FONCTION> .*fonction_not_increasing\.lua:5: function of INST: abscissas must be strictly increasing, but INST\[2\] = 0\.5 follows INST\[1\] = 1 \(0-based indices\)
-- DEFI_FONCTION with abscissas that decrease.
DEBUT{}
F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0, 0.5, 2.0}}
FIN{}
