-- expect-exit: 2
-- expect-output: <F> <TEST_RESU> .*co_made_after_the_concept\.lua:12: MAILLAGE\[1\]: keyword MAILLAGE expects a maillage_sdaster, got CO\('MA_2'\)
-- A CO box stands for the concept a macro made under its name only when the box
-- was made before: CO('MA_2') made afterwards asks for a new concept, it is not
-- the mesh.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../program/square_quad4.mail'}
MA = {}
MA[1] = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MA[2] = CO('MA_2')
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA[1], MAILLAGE_NP1 = MA[2]}
AGAIN = CO('MA_2')
TEST_RESU{MAILLAGE = {MAILLAGE = AGAIN, CARA = 'NB_NOEUD', VALE_CALC_I = 9}}
