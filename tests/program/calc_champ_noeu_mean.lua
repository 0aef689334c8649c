-- expect-exit: 0
-- expect-output: <I> checks: 10 OK, 0 NOOK
-- NOEU fields are the arithmetic mean of the ELNO values of the cells around each node,
-- as in code_aster. Two QUAD4 side by side (two_quad4.mail: M1 = [0, 1] x [0, 1], E = 1000;
-- M2 = [1, 2] x [0, 1], E = 3000; NU = 0, D_PLAN), every node moved by DX = 0.01 X, DY = 0:
-- the strain is EPXX = 0.01 in both, so SIXX = E EPXX is 10 in M1 and 30 in M2, uniform in
-- each. SIGM_NOEU: 10 at N1 and N4 (M1 only), 30 at N3 and N6 (M2 only), (10 + 30) / 2 = 20
-- at N2 and N5 (both). Computed on M1 alone (GROUP_MA), N2 holds M1's 10. SIEQ_NOEU's VMIS
-- is the mean of the ELNO von Mises values (SIZZ = 0 with NU = 0): 20 at N5. R2 read back
-- (getField) is defined on the 4 nodes of M1 only: its smallest SIXX is 10 (not a 0 elsewhere).
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'two_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MA = DEFI_GROUP{reuse = MA, MAILLAGE = MA, CREA_GROUP_MA = {{NOM = 'C1', MAILLE = 'M1'}, {NOM = 'C2', MAILLE = 'M2'}}}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
SOFT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.0}}
HARD = DEFI_MATERIAU{ELAS = {E = 3000.0, NU = 0.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {{GROUP_MA = 'C1', MATER = SOFT}, {GROUP_MA = 'C2', MATER = HARD}}}
UX = FORMULE{VALE = '0.01*X', NOM_PARA = {'X', 'Y'}}
ZERO = FORMULE{VALE = '0*X', NOM_PARA = {'X', 'Y'}}
BC = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {TOUT = 'OUI', DX = UX, DY = ZERO}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
R1 = CALC_CHAMP{RESULTAT = R, CONTRAINTE = 'SIGM_NOEU', CRITERES = 'SIEQ_NOEU'}
R2 = CALC_CHAMP{RESULTAT = R, GROUP_MA = 'C1', CONTRAINTE = 'SIGM_NOEU'}
local function check(res, node, cmp, v, field)
  return {RESULTAT = res, INST = 0.0, NOM_CHAM = field or 'SIGM_NOEU', NOEUD = node, NOM_CMP = cmp, VALE_CALC = v,
          REFERENCE = 'ANALYTIQUE', VALE_REFE = v, PRECISION = 1e-10}
end
TEST_RESU{RESU = {
  check(R1, 'N1', 'SIXX', 10.0), check(R1, 'N4', 'SIXX', 10.0), check(R1, 'N3', 'SIXX', 30.0),
  check(R1, 'N6', 'SIXX', 30.0), check(R1, 'N2', 'SIXX', 20.0), check(R1, 'N5', 'SIXX', 20.0),
  check(R1, 'N5', 'VMIS', 20.0, 'SIEQ_NOEU'),
  check(R2, 'N2', 'SIXX', 10.0), check(R2, 'N5', 'SIXX', 10.0),
}}
-- R2's SIGM_NOEU is defined at the nodes of M1 only: the field read back says so.
S2 = R2:getField('SIGM_NOEU', 0.0)
TEST_RESU{CHAM_NO = {CHAM_GD = S2, TYPE_TEST = 'MIN', NOM_CMP = 'SIXX', VALE_CALC = 10.0,
                     REFERENCE = 'ANALYTIQUE', VALE_REFE = 10.0, PRECISION = 1e-10}}
