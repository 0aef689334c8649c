-- expect-exit: 2
-- expect-output: <F> <TEST_TABLE> .*test_table_text_on_real_column\.lua:10: column V holds reals: give VALE_CALC
-- VALE_CALC_K on a column of reals.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
T = CREA_TABLE{LISTE = {{PARA = 'V', LISTE_R = {0.5}}}}
TEST_TABLE{TABLE = T, NOM_PARA = 'V', VALE_CALC_K = '0.5'}
FIN{}
