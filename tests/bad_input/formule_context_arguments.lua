-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_context_arguments\.lua:6: VALE: function 'G' takes 1 argument \(X\), got 2 at column 1 in "G\(X, 1\)"
-- A FORMULE calling a function of its context with the wrong number of arguments.
DEBUT{}
G = FORMULE{VALE = 'X**2', NOM_PARA = 'X'}
F = FORMULE{VALE = 'G(X, 1)', G = G, NOM_PARA = 'X'}
FIN{}
