-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_reference_non_regression\.lua:9: CHAM_NO\[1\]: keyword REFERENCE = 'NON_REGRESSION' is not allowed; allowed values: 'ANALYTIQUE', 'SOURCE_EXTERNE', 'AUTRE_ASTER', 'NON_DEFINI'
-- REFERENCE names the origin of VALE_REFE: NON_REGRESSION is not one (it is the check with VALE_CALC).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
TEST_RESU{CHAM_NO = {CHAM_GD = U, NOEUD = 'N1', NOM_CMP = 'DX', VALE_CALC = 0.5, REFERENCE = 'NON_REGRESSION'}}
FIN{}
