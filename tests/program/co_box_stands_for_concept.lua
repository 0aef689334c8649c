-- expect-exit: 0
-- expect-output: <I> checks: 6 OK, 0 NOOK
-- code_aster's idiom for a macro's output: a variable holds CO('name'), the macro
-- makes the concept of that name, and the variable then stands for the concept
-- (MA[2] below, as ssnp150b's loop of refinements writes it). Uniform refinement
-- of one QUAD4 and its four SEG2 edges: 4 + 8 = 12 cells, 9 nodes; once more:
-- 16 + 16 = 32 cells, 25 nodes; the group HAUT of MA_2 holds 2 edges.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = {}
MA[1] = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MA[2] = CO('MA_2')
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA[1], MAILLAGE_NP1 = MA[2]}
TEST_RESU{MAILLAGE = {{MAILLAGE = MA[2], CARA = 'NB_MAILLE', VALE_CALC_I = 12},
                      {MAILLAGE = MA[2], CARA = 'NB_NOEUD', VALE_CALC_I = 9},
                      {MAILLAGE = MA_2, CARA = 'NB_NOEUD', VALE_CALC_I = 9}}}
MO = AFFE_MODELE{MAILLAGE = MA[2], AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MA[3] = CO('MA_3')
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA[2], MAILLAGE_NP1 = MA[3]}
TEST_RESU{MAILLAGE = {{MAILLAGE = MA[3], CARA = 'NB_MAILLE', VALE_CALC_I = 32},
                      {MAILLAGE = MA[3], CARA = 'NB_NOEUD', VALE_CALC_I = 25}}}
TEST_RESU{MAILLAGE = {MAILLAGE = MA_2, CARA = 'NB_MA_GROUP_MA', NOM_GROUP_MA = 'HAUT', VALE_CALC_I = 2}}
