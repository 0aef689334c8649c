-- expect-exit: 2
-- expect-output: <F> <TEST_FONCTION> .*fatal_wrong_concept_type.lua:5: VALEUR\[1\]: keyword FONCTION expects .*got a listr8_sdaster
-- A concept of the wrong type: the message names the keyword and the expected types.
L = DEFI_LIST_REEL{VALE = {0, 1}}
TEST_FONCTION{VALEUR = {FONCTION = L, VALE_PARA = 0.5, VALE_CALC = 0.5}}
