-- expect-exit: 0
-- expect-output: DEFI_CONTACT \(INFO=2\): contact at the converged instant \(CONT_NOEU\)
-- CONT_NOEU of both formulations against the exact solution: a block of 2 x 2
-- QUAD8 (E = 1, NU = 0.3, D_PLAN) pressed onto a flat rigid master by a uniform
-- traction p on its top, sides free. The stress is uniform, sigma_yy = -p, so at
-- every slave node RN = -p, JEU = 0, CONT = 1, RNX = 0 and RNY = p times the
-- node's share of BAS (cells of length h = 0.5: h/6 = 1/12 at the corner COIN,
-- 2h/3 = 1/3 at the middle node BAS_MIL, 2 h/6 = 1/6 at BAS_CEN); the top
-- moves by -(1 - NU^2) p / E.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../bad_input/contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
P = 0.01
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0},
                    FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -P}}
FIXE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {GROUP_MA = {'MAITRE', 'MAITRE_BAS'}, DX = 0.0, DY = 0.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}

CD = DEFI_CONTACT{MODELE = MO, FORMULATION = 'DISCRETE', INFO = 2,
                  ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}
CC = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}
for _, c in ipairs({{'RD', CD}, {'RC', CC}}) do
  _G[c[1]] = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = CH}, {CHARGE = FIXE}}, CONTACT = c[2],
                           COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
end

local function exact(R, group, cmp, value)
  if value == 0 then
    TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'CONT_NOEU', GROUP_NO = group, NOM_CMP = cmp,
                      VALE_CALC = 0.0, CRITERE = 'ABSOLU', TOLE_MACHINE = 1e-12, ORDRE_GRANDEUR = 1.0,
                      REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, PRECISION = 1e-12}}
  else
    TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'CONT_NOEU', GROUP_NO = group, NOM_CMP = cmp,
                      VALE_CALC = value, REFERENCE = 'ANALYTIQUE', VALE_REFE = value, PRECISION = 1e-9}}
  end
end
for _, R in ipairs({RD, RC}) do
  for group, share in pairs({COIN = 1 / 12, BAS_MIL = 1 / 3, BAS_CEN = 1 / 6}) do
    exact(R, group, 'CONT', 1.0)
    exact(R, group, 'JEU', 0)
    exact(R, group, 'RN', -P)
    exact(R, group, 'RNX', 0)
    exact(R, group, 'RNY', P * share)
  end
  TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'DEPL', GROUP_NO = 'HAUT_CEN', NOM_CMP = 'DY',
                    VALE_CALC = -(1 - 0.09) * P, REFERENCE = 'ANALYTIQUE', VALE_REFE = -(1 - 0.09) * P,
                    PRECISION = 1e-9}}
end
TEST_RESU{RESU = {RESULTAT = RC, INST = 1.0, NOM_CHAM = 'DEPL', GROUP_NO = 'BAS_CEN', NOM_CMP = 'LAGS_C',
                  VALE_CALC = -P, REFERENCE = 'ANALYTIQUE', VALE_REFE = -P, PRECISION = 1e-9}}
