-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_without_vale_calc\.lua:9: CHAM_NO\[1\]: exactly one of VALE_CALC, VALE_CALC_I is required, got none \(rule UN_PARMI\('VALE_CALC', 'VALE_CALC_I'\)\)
-- Every check has its non-regression value: VALE_CALC (or VALE_CALC_I) is required.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
TEST_RESU{CHAM_NO = {CHAM_GD = U, NOEUD = 'N1', NOM_CMP = 'DX', REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.5}}
FIN{}
