-- expect-exit: 0
-- expect-output: <I> checks: 2 OK, 0 NOOK
-- TEST_RESU on a nodal field with MAILLE beside NOEUD, as code_aster's studies write it
-- (ssnd104a): the cell says no more than the node. One QUAD4 (plastic_square.mail),
-- E = 1000, NU = 0, pulled by DY = 0.01 on HAUT with DY = 0 on BAS and DX = 0 on GAUCHE:
-- uniaxial, SIYY = E 0.01 = 10 everywhere, DY = 0.01 at N3.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0},
                                             {GROUP_MA = 'HAUT', DY = 0.01}}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, CONTRAINTE = {'SIGM_ELNO', 'SIGM_NOEU'}}
TEST_RESU{RESU = {
  {RESULTAT = R, INST = 0.0, NOM_CHAM = 'DEPL', NOEUD = 'N3', MAILLE = 'M1', NOM_CMP = 'DY',
   VALE_CALC = 0.01, VALE_REFE = 0.01, REFERENCE = 'ANALYTIQUE', PRECISION = 1e-12},
  {RESULTAT = R, INST = 0.0, NOM_CHAM = 'SIGM_NOEU', NOEUD = 'N3', MAILLE = 'M1', NOM_CMP = 'SIYY',
   VALE_CALC = 10.0, VALE_REFE = 10.0, REFERENCE = 'ANALYTIQUE', PRECISION = 1e-12},
}}
FIN{}
