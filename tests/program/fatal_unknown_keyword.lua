-- expect-exit: 2
-- expect-output: <F> <DEBUT> .*fatal_unknown_keyword.lua:4: keyword PARLOT is not a keyword of DEBUT; did you mean PAR_LOT\?
print('before')
DEBUT{PARLOT = 'NON'}
