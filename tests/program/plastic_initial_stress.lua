-- expect-exit: 0
-- expect-output: <I> checks: 4 OK, 0 NOOK
-- ETAT_INIT SIGM from CREA_CHAMP CART_SIEF_R: a prestress SIYY = S0 = 100 (below SY) in
-- the unit square of one QUAD4 (plastic_square.mail), C_PLAN, VMIS_ISOT_LINE with E = 200000,
-- NU = 0.3, ET = 2000, SY = 200; DY = 0 on BAS, DX = 0 on GAUCHE, DY = e = 0.002 on HAUT in one
-- step. The prestress is balanced by the reactions of BAS and HAUT (SIXX = 0 on the free
-- edge). Uniaxial stress from S0: the trial stress S0 + E e = 500 exceeds SY, and one radial
-- return (exact here: the direction stays the axis) gives p = (S0 + E e - SY) / (E + H),
-- SIYY = SY + H p, H = E ET / (E - ET). Without the prestress p would be (E e - SY) / (E + H).
-- At INST 0 the stored state is the prestress itself, with V1 = 0. The plane stress return
-- holds the yield condition to RESI_INTE_RELA x SY: 1e-14 here, for the closed form to 1e-9.
local E, NU, ET, SY, S0, e = 200000.0, 0.3, 2000.0, 200.0, 100.0, 0.002
local H = E * ET / (E - ET)
local p = (S0 + E * e - SY) / (E + H)
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, ECRO_LINE = {D_SIGM_EPSI = ET, SY = SY}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DY = 1.0}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, e}}
SIG0 = CREA_CHAMP{TYPE_CHAM = 'CART_SIEF_R', OPERATION = 'AFFE', MODELE = MO,
                  AFFE = {TOUT = 'OUI', NOM_CMP = {'SIXX', 'SIYY', 'SIZZ', 'SIXY'}, VALE = {0.0, S0, 0.0, 0.0}}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = RAMPE}},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', RESI_INTE_RELA = 1e-14}, ETAT_INIT = {SIGM = SIG0}, INCREMENT = {LIST_INST = L},
                  CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
local function ref(v, inst, cham, cmp, point)
  return {RESULTAT = R, INST = inst, NOM_CHAM = cham, NOM_CMP = cmp, MAILLE = 'M1', POINT = point,
          REFERENCE = 'ANALYTIQUE', VALE_REFE = v, VALE_CALC = v, CRITERE = 'ABSOLU',
          PRECISION = cham == 'SIEF_ELGA' and 1e-9 or 1e-12, ORDRE_GRANDEUR = v == 0.0 and 1.0 or nil}
end
TEST_RESU{RESU = {
  ref(S0, 0.0, 'SIEF_ELGA', 'SIYY', 1),
  ref(0.0, 0.0, 'VARI_ELGA', 'V1', 1),
  ref(SY + H * p, 1.0, 'SIEF_ELGA', 'SIYY', 3),
  ref(p, 1.0, 'VARI_ELGA', 'V1', 4),
}}
