-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_vale_calc_i_on_field\.lua:9: CHAM_NO\[1\]: the field U holds real values: give VALE_CALC \(and VALE_REFE\), not VALE_CALC_I
-- Fields hold reals: VALE_CALC_I is refused, as code_aster does.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
TEST_RESU{CHAM_NO = {CHAM_GD = U, NOEUD = 'N1', NOM_CMP = 'DX', VALE_CALC_I = 1}}
FIN{}
