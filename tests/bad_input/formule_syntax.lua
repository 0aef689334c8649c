-- expect-exit: 2
-- expect-output: <F> <FORMULE> .*formule_syntax\.lua:5: VALE: unterminated expression: an operand is expected after '\+' at column 8 in "2 \* \(X \+ "
-- A FORMULE with a syntax error.
DEBUT{}
F = FORMULE{VALE = '2 * (X + ', NOM_PARA = 'X'}
FIN{}
