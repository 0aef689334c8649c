-- expect-exit: 2
-- expect-output: <F> <POURSUITE> .*poursuite_first.lua:4: POURSUITE continues a study begun in an earlier file, and no study file ran before this one
-- POURSUITE in the first (here the only) study file of a run: there is nothing to continue.
POURSUITE{}
F = FORMULE{VALE = '2*X', NOM_PARA = {'X'}}
