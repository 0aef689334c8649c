-- expect-exit: 0
-- DEFI_CONTACT's options end to end, against exact solutions, on the block of
-- contact_block.mail (2 x 2 QUAD8, E = 1, NU = 0.3, D_PLAN, small strain):
--  * ALGO_CONT='PENALISATION' (DISCRETE E_N, CONTINUE COEF_PENA_CONT = 100) under
--    a uniform traction p = 0.01 on the top: every slave node penetrates by
--    p / 100 (JEU = -1E-4), RN = -p, the top moves by -p/100 - (1 - NU^2) p.
--  * DIST_APPA: the top pushed down by 0.2 onto MAITRE_BAS, 0.1 below BAS: the
--    bottom stops at -0.1 and RN = E / (1 - NU^2) * (-0.1); with DIST_APPA =
--    0.05 BAS is never paired and goes to -0.2.
--  * SANS_GROUP_NO (DISCRETE): the corner COIN, held by DY = 0, excluded from
--    contact: its share of the load goes to the support, the rest is exact.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../bad_input/contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
P = 0.01
GAUCHE = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0}}
PRESS = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -P}}
PUSH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DY = -0.2}}
COIN = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_NO = 'COIN', DY = 0.0}}
FIXE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {GROUP_MA = {'MAITRE', 'MAITRE_BAS'}, DX = 0.0, DY = 0.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}

local function solve(contact, loads)
  local excit = {{CHARGE = GAUCHE}, {CHARGE = FIXE}}
  for _, l in ipairs(loads) do excit[#excit + 1] = {CHARGE = l} end
  return STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = excit, CONTACT = contact,
                       COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
end
local function exact(R, field, group, cmp, value)
  if value == 0 then
    TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = field, GROUP_NO = group, NOM_CMP = cmp,
                      VALE_CALC = 0.0, CRITERE = 'ABSOLU', TOLE_MACHINE = 1e-12, ORDRE_GRANDEUR = 1.0,
                      REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, PRECISION = 1e-12}}
  else
    TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = field, GROUP_NO = group, NOM_CMP = cmp,
                      VALE_CALC = value, REFERENCE = 'ANALYTIQUE', VALE_REFE = value, PRECISION = 1e-9}}
  end
end

-- Penalisation.
PEN_D = solve(DEFI_CONTACT{MODELE = MO, FORMULATION = 'DISCRETE',
                           ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'PENALISATION', E_N = 100.0}},
              {PRESS})
PEN_C = solve(DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE',
                           ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'PENALISATION',
                                   COEF_PENA_CONT = 100.0}},
              {PRESS})
for _, R in ipairs({PEN_D, PEN_C}) do
  for _, g in ipairs({'COIN', 'BAS_MIL', 'BAS_CEN'}) do
    exact(R, 'CONT_NOEU', g, 'CONT', 1.0)
    exact(R, 'CONT_NOEU', g, 'JEU', -P / 100)
    exact(R, 'CONT_NOEU', g, 'RN', -P)
  end
  exact(R, 'DEPL', 'HAUT_CEN', 'DY', -P / 100 - (1 - 0.09) * P)
end
exact(PEN_C, 'DEPL', 'BAS_MIL', 'LAGS_C', -P)

-- DIST_APPA.
for _, f in ipairs({'DISCRETE', 'CONTINUE'}) do
  local paired = solve(DEFI_CONTACT{MODELE = MO, FORMULATION = f,
                                    ZONE = {GROUP_MA_MAIT = 'MAITRE_BAS', GROUP_MA_ESCL = 'BAS'}}, {PUSH})
  exact(paired, 'DEPL', 'BAS_CEN', 'DY', -0.1)
  exact(paired, 'CONT_NOEU', 'BAS_CEN', 'RN', -0.1 / (1 - 0.09))
  local far = solve(DEFI_CONTACT{MODELE = MO, FORMULATION = f,
                                 ZONE = {GROUP_MA_MAIT = 'MAITRE_BAS', GROUP_MA_ESCL = 'BAS', DIST_APPA = 0.05}}, {PUSH})
  exact(far, 'DEPL', 'BAS_CEN', 'DY', -0.2)
  exact(far, 'CONT_NOEU', 'BAS_CEN', 'CONT', 0)
  exact(far, 'CONT_NOEU', 'BAS_CEN', 'RN', 0)
end

-- SANS_GROUP_NO.
SANS = solve(DEFI_CONTACT{MODELE = MO, FORMULATION = 'DISCRETE',
                          ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', SANS_GROUP_NO = 'COIN'}},
             {PRESS, COIN})
exact(SANS, 'CONT_NOEU', 'COIN', 'CONT', 0)
exact(SANS, 'CONT_NOEU', 'COIN', 'RN', 0)
exact(SANS, 'CONT_NOEU', 'COIN', 'RNY', 0)
exact(SANS, 'CONT_NOEU', 'BAS_MIL', 'RN', -P)
exact(SANS, 'CONT_NOEU', 'BAS_MIL', 'RNY', P / 3)
exact(SANS, 'REAC_NODA', 'COIN', 'DY', P / 12)  -- the support takes the corner's share
exact(SANS, 'DEPL', 'HAUT_CEN', 'DY', -(1 - 0.09) * P)
