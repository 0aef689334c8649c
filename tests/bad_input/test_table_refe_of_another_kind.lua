-- expect-exit: 2
-- expect-output: <F> <TEST_TABLE> .*test_table_refe_of_another_kind\.lua:10: VALE_CALC_I needs VALE_REFE_I \(the same kind of value\)
-- VALE_CALC_I with a real VALE_REFE: the two values are of the same kind.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
T = CREA_TABLE{LISTE = {{PARA = 'N', LISTE_I = {3}}}}
TEST_TABLE{TABLE = T, NOM_PARA = 'N', VALE_CALC_I = 3, REFERENCE = 'ANALYTIQUE', VALE_REFE = 3.0}
FIN{}
