-- expect-exit: 1
-- expect-output: SKIP  NON_REGRESSION.*NOOK  NON_REGRESSION.*<I> checks: 18 OK, 1 NOOK
-- The .resu layout of every kind of check, on values exact in binary (0.5, -0.25,
-- sums of them; SOMM_ABS of S: 2 cells x 4 Gauss points x (2 + 0.5) = 20), compared line by line with resu_layout.expected (written by hand
-- from code_aster's layout: tests/program/CMakeLists.txt runs the comparison).
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'two_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.5, -0.25}}}
S = CREA_CHAMP{TYPE_CHAM = 'ELGA_SIEF_R', OPERATION = 'AFFE', MODELE = MO,
               AFFE = {GROUP_MA = 'SURFACE', NOM_CMP = {'SIXX', 'SIYY'}, VALE = {2.0, -0.5}}}
Z = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.0, 1e-9}}}
-- MAILLAGE's checks come first, whatever the order of the keywords (code_aster's order).
TEST_RESU{CHAM_NO = {
  {CHAM_GD = U, NOEUD = 'N3', NOM_CMP = 'DX', VALE_CALC = 0.5, REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.5},
  {CHAM_GD = U, TYPE_TEST = 'SOMM', NOM_CMP = 'DY', VALE_CALC = -1.5},
  {CHAM_GD = U, GROUP_NO = 'COIN', NOM_CMP = 'DY', VALE_ABS = 'OUI', VALE_CALC = 0.25, LEGENDE = 'ABS'},
}, MAILLAGE = {
  {MAILLAGE = MA, CARA = 'NB_MAILLE', VALE_CALC_I = 7},
  {MAILLAGE = MA, CARA = 'NB_MA_GROUP_MA', NOM_GROUP_MA = 'SURFACE', VALE_CALC_I = 2, REFERENCE = 'ANALYTIQUE',
   VALE_REFE_I = 2},
}}
TEST_RESU{CHAM_ELEM = {
  {CHAM_GD = S, MAILLE = 'M2', POINT = 3, NOM_CMP = 'SIYY', VALE_CALC = -0.5},
  {CHAM_GD = S, TYPE_TEST = 'SOMM_ABS', VALE_CALC = 20.0},
}}
-- A zero VALE_CALC: skipped without ORDRE_GRANDEUR, absolute within 1e-6 * 1000 with it.
TEST_RESU{CHAM_NO = {
  {CHAM_GD = Z, NOEUD = 'N1', NOM_CMP = 'DX', VALE_CALC = 0.0},
  {CHAM_GD = Z, NOEUD = 'N1', NOM_CMP = 'DY', VALE_CALC = 0.0, ORDRE_GRANDEUR = 1000.0, CRITERE = 'ABSOLU'},
}}
T = CREA_TABLE{LISTE = {{PARA = 'NOM', LISTE_K = {'A', 'B'}}, {PARA = 'N', LISTE_I = {3, 4}},
                        {PARA = 'V', LISTE_R = {0.5, 0.75}}}}
TEST_TABLE{TABLE = T, NOM_PARA = 'V', FILTRE = {NOM_PARA = 'NOM', VALE_K = 'B'}, VALE_CALC = 0.75}
TEST_TABLE{TABLE = T, NOM_PARA = 'N', TYPE_TEST = 'SOMM', VALE_CALC_I = 7}
TEST_TABLE{TABLE = T, NOM_PARA = 'NOM', FILTRE = {NOM_PARA = 'N', VALE_I = 3}, VALE_CALC_K = 'A'}
-- Texts compare without trailing blanks, as Fortran compares them.
TEST_TABLE{TABLE = T, NOM_PARA = 'NOM', FILTRE = {NOM_PARA = 'N', VALE_I = 4}, VALE_CALC_K = 'B  ', REFERENCE = 'AUTRE_ASTER',
           VALE_REFE_K = 'B'}
F = FORMULE{VALE = 'X/4', NOM_PARA = 'X'}
TEST_FONCTION{VALEUR = {FONCTION = F, NOM_PARA = 'X', VALE_PARA = 2.0, VALE_CALC = 0.5,
                        REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.5}}
-- A result: every node imposed (AFFE_CHAR_CINE), DEPL is exactly the imposed values.
-- INST = 1e-4 finds the instant 0 only absolutely: CRITERE and TOLE_MACHINE's second values.
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.25}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {TOUT = 'OUI', DX = 0.5, DY = -0.25}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
TEST_RESU{RESU = {
  {RESULTAT = R, INST = 0.0, NOM_CHAM = 'DEPL', NOEUD = 'N4', NOM_CMP = 'DX', VALE_CALC = 0.5},
  {RESULTAT = R, INST = 1e-4, CRITERE = {'RELATIF', 'ABSOLU'}, TOLE_MACHINE = {1e-6, 1e-3}, NOM_CHAM = 'DEPL',
   GROUP_NO = 'COIN', NOM_CMP = 'DY', VALE_CALC = -0.25},
  {RESULTAT = R, NUME_ORDRE = 1, PARA = 'INST', VALE_CALC = 0.0, ORDRE_GRANDEUR = 1.0, CRITERE = 'ABSOLU'},
  {RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', TYPE_TEST = 'MAX', VALE_CALC = 0.5},
}, INFO = 2}
-- A deliberately wrong VALE_CALC (0.3 for 0.5): NOOK.
TEST_RESU{CHAM_NO = {CHAM_GD = U, NOEUD = 'N2', NOM_CMP = 'DX', VALE_CALC = 0.3}}
FIN{}
