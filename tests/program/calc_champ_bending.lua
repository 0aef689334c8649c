-- expect-exit: 0
-- expect-output: CALC_CHAMP: EPSI_ELNO, EPSI_NOEU, SIEQ_ELNO, SIEQ_NOEU, SIGM_ELNO, SIGM_NOEU at 1 instant\(s\), on 8 cell\(s\).*CALC_CHAMP: SIGM_ELNO, SIGM_NOEU at 1 instant\(s\), on 4 cell\(s\).*<I> checks: 19 OK, 0 NOOK
-- MECA_STATIQUE + CALC_CHAMP + TEST_RESU on a stress that varies: pure bending of the
-- beam [0, 4] x [-0.5, 0.5] in plane stress (4 x 2 QUAD8, calc_champ_bending.mail),
-- E = 1000, NU = 0.25, with the exact displacement imposed on the whole boundary:
--   u_x = K x y, u_y = -K (x^2 + NU y^2) / 2, K = 0.01,
-- whose strain is EPXX = K y, EPYY = -NU K y, EPXY = 0 (EPZZ = -NU K y, the plane stress
-- one), and whose stress is SIXX = E K y alone. QUAD8 holds this displacement exactly, so
-- the stresses at the Gauss points are exact; the extrapolation to the cell nodes
-- reproduces a field linear in the reference coordinates, so SIGM_ELNO and SIGM_NOEU are
-- exact too. Cell M8 = [3, 4] x [0, 0.5]: code_aster's FPG9 numbers the corner points
-- counterclockwise, then the mid-edge points, then the centre: point 1 is at eta =
-- -sqrt(3/5), y = 0.25 (1 - sqrt(3/5)), point 3 at y = 0.25 (1 + sqrt(3/5)), point 9 (the
-- centre) at y = 0.25, point 7 (mid-edge, eta = sqrt(3/5)) as point 3. NA = (4, 0.5),
-- NB = (2, 0.5), NC = (3, 0.25). SIEQ at NA: SIXX = 5 alone, VMIS = TRESCA = PRIN_3 = 5,
-- PRIN_1 = PRIN_2 = 0, TRIAX = 1/3. CALC_CHAMP without reuse makes a new result; with
-- GROUP_MA the nodal mean is over those cells only (NB lies on M7, in HALF_RIGHT).
local E, NU, K = 1000.0, 0.25, 0.01
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'calc_champ_bending.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
UX = FORMULE{VALE = 'K*X*Y', NOM_PARA = {'X', 'Y'}, K = K}
UY = FORMULE{VALE = '-K*(X*X + NU*Y*Y)/2', NOM_PARA = {'X', 'Y'}, K = K, NU = NU}
BC = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BORD', DX = UX, DY = UY}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}, INST = 1.0}
R2 = CALC_CHAMP{RESULTAT = R, CONTRAINTE = {'SIGM_NOEU'}, DEFORMATION = {'EPSI_NOEU'}, CRITERES = {'SIEQ_NOEU'}}
R3 = CALC_CHAMP{RESULTAT = R, GROUP_MA = 'HALF_RIGHT', INST = 1.0, CONTRAINTE = 'SIGM_NOEU'}

local a = math.sqrt(0.6)
local function ref(v) return {VALE_CALC = v, REFERENCE = 'ANALYTIQUE', VALE_REFE = v, PRECISION = 1e-9} end
local function check(t)
  local occ = ref(t.v)
  t.v = nil
  for key, value in pairs(t) do occ[key] = value end
  occ.INST = occ.INST or 1.0
  return occ
end
TEST_RESU{RESU = {
  check{RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', GROUP_MA = 'CELL_A', POINT = 1, NOM_CMP = 'SIXX', v = E * K * 0.25 * (1 - a)},
  check{RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', MAILLE = 'M8', POINT = 3, NOM_CMP = 'SIXX', v = E * K * 0.25 * (1 + a)},
  check{RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', MAILLE = 'M8', POINT = 7, NOM_CMP = 'SIXX', v = E * K * 0.25 * (1 + a)},
  check{RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', MAILLE = 'M8', POINT = 9, NOM_CMP = 'SIXX', v = E * K * 0.25},
  check{RESULTAT = R2, NOM_CHAM = 'SIGM_ELNO', MAILLE = 'M8', GROUP_NO = 'NA', NOM_CMP = 'SIXX', v = E * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'SIGM_ELNO', GROUP_MA = 'CELL_A', GROUP_NO = 'NC', NOM_CMP = 'SIXX', v = E * K * 0.25},
  check{RESULTAT = R2, NOM_CHAM = 'SIGM_ELNO', GROUP_MA = 'CELL_A', POINT = 8, NOM_CMP = 'SIXX', v = E * K * 0.25},
  check{RESULTAT = R2, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'NB', NOM_CMP = 'SIXX', v = E * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'NC', NOM_CMP = 'SIXX', v = E * K * 0.25},
  check{RESULTAT = R2, NOM_CHAM = 'SIGM_NOEU', TYPE_TEST = 'MAX', NOM_CMP = 'SIXX', v = E * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'SIGM_NOEU', TYPE_TEST = 'MIN', NOM_CMP = 'SIXX', v = -E * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'EPSI_NOEU', GROUP_NO = 'NA', NOM_CMP = 'EPYY', v = -NU * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'EPSI_ELNO', MAILLE = 'M8', NOEUD = 'N35', NOM_CMP = 'EPZZ', v = -NU * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'SIEQ_NOEU', GROUP_NO = 'NA', NOM_CMP = 'VMIS', v = E * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'SIEQ_NOEU', GROUP_NO = 'NA', NOM_CMP = 'TRESCA', v = E * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'SIEQ_ELNO', GROUP_MA = 'CELL_A', GROUP_NO = 'NA', NOM_CMP = 'PRIN_3', v = E * K * 0.5},
  check{RESULTAT = R2, NOM_CHAM = 'SIEQ_NOEU', GROUP_NO = 'NA', NOM_CMP = 'TRIAX', v = 1 / 3},
  check{RESULTAT = R3, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'NB', NOM_CMP = 'SIXX', v = E * K * 0.5},
  check{RESULTAT = R3, NOM_CHAM = 'SIGM_NOEU', TYPE_TEST = 'MIN', NOM_CMP = 'SIXX', v = -E * K * 0.5},
}}
-- The new results hold DEPL too.
if #R2:getField('DEPL', 1.0):getValues() ~= 2 * MA:getNumberOfNodes() then error('R2 has no DEPL') end
S = CREA_CHAMP{TYPE_CHAM = 'NOEU_SIEF_R', OPERATION = 'EXTR', RESULTAT = R3, NOM_CHAM = 'SIGM_NOEU', INST = 1.0}
IMPR_RESU{FORMAT = 'RESULTAT', RESU = {RESULTAT = R2, NOM_CHAM = {'SIGM_ELNO', 'SIGM_NOEU'}, GROUP_MA = 'CELL_A'}}
