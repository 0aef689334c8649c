-- Part 2: F of part 1 checked against a wrong value (2*4 + 1 = 9, not 10): NOOK. The
-- summary and the exit status (1) cover both files: 1 OK, 1 NOOK.
POURSUITE{}
TEST_FONCTION{VALEUR = {FONCTION = F, VALE_PARA = 4.0, VALE_CALC = 10.0}}
