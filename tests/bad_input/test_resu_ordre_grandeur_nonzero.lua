-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*test_resu_ordre_grandeur_nonzero\.lua:9: CHAM_NO\[1\]: ORDRE_GRANDEUR is allowed only with VALE_CALC = 0 \(it scales the absolute tolerance of a zero value\)
-- ORDRE_GRANDEUR belongs to a VALE_CALC of 0 (code_aster's catalogue offers it only then).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
TEST_RESU{CHAM_NO = {CHAM_GD = U, NOEUD = 'N1', NOM_CMP = 'DX', VALE_CALC = 0.5, ORDRE_GRANDEUR = 1.0}}
FIN{}
