-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_unknown_name\.lua:5: VALE: unknown name 'Z' at column 5 \(parameters: X\) in "X \+ Z"
-- A FORMULE using a name that is not one of its parameters.
DEBUT{}
F = FORMULE{VALE = 'X + Z', NOM_PARA = 'X'}
FIN{}
