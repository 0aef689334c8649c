-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_tole_machine_pair_outside_resu\.lua:9: CHAM_NO\[1\]: keyword TOLE_MACHINE takes at most 1 value, got 2
-- TOLE_MACHINE takes two values only in RESU (the second finds INST).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
TEST_RESU{CHAM_NO = {CHAM_GD = U, NOEUD = 'N1', NOM_CMP = 'DX', VALE_CALC = 0.5, TOLE_MACHINE = {1e-6, 1e-6}}}
FIN{}
