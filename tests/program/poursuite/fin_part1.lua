-- Part 1 of a two-file run (fin_part2.lua follows): one check OK, then FIN, which
-- ends this file only: the error after it never runs, the second file does.
F = FORMULE{VALE = '2*X + 1', NOM_PARA = {'X'}}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 3.0, VALE_CALC = 7.0}}
FIN{}
error('a command after FIN ran')
