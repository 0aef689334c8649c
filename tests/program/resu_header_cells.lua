-- expect-exit: 0
-- expect-output:  ---- RESULTAT         NUME_ORDRE       NOM_CHAM         NOM_CMP          MAILLE           POINT.      R                1                SIEF_ELGA        SIXX             M1               2..* ---- RESULTAT         NUME_ORDRE       NOM_CHAM         NOM_CMP          NOEUD            MAILLE           POINT.      R                1                SIGM_ELNO        SIYY             N6               M2               0..* ---- RESULTAT         NUME_ORDRE       NOM_CHAM         NOM_CMP          TYPE_TEST        NOM_CMP.      R                1                SIEF_ELGA        SIXY             MAX              SIXY..*<I> checks: 3 OK, 0 NOOK
-- The header of RESU's checks on fields on cells, in code_aster's order: NOM_CMP,
-- then the node (ELNO), the cell and POINT (0 when a node designates the point);
-- TYPE_TEST repeats the component. A rigid translation: stresses are 0 to rounding.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'two_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.25}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {TOUT = 'OUI', DX = 0.5, DY = -0.25}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, CONTRAINTE = 'SIGM_ELNO'}
TEST_RESU{RESU = {
  {RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIEF_ELGA', MAILLE = 'M1', POINT = 2, NOM_CMP = 'SIXX',
   VALE_CALC = 0.0, CRITERE = 'ABSOLU', ORDRE_GRANDEUR = 1.0},
  {RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_ELNO', MAILLE = 'M2', NOEUD = 'N6', NOM_CMP = 'SIYY',
   VALE_CALC = 0.0, CRITERE = 'ABSOLU', ORDRE_GRANDEUR = 1.0},
  {RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'SIEF_ELGA', TYPE_TEST = 'MAX', NOM_CMP = 'SIXY',
   VALE_CALC = 0.0, CRITERE = 'ABSOLU', ORDRE_GRANDEUR = 1.0},
}}
-- TEST_NAN alone: accepted, no check.
TEST_RESU{TEST_NAN = 'OUI'}
FIN{}
