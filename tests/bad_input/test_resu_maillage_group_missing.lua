-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_maillage_group_missing\.lua:6: MAILLAGE\[1\]: CARA='NB_NO_GROUP_NO' counts the members of a group: give NOM_GROUP_NO
-- NB_NO_GROUP_NO counts the nodes of a group: NOM_GROUP_NO names it.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
TEST_RESU{MAILLAGE = {MAILLAGE = MA, CARA = 'NB_NO_GROUP_NO', VALE_CALC_I = 1}}
FIN{}
