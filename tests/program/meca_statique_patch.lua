-- expect-exit: 0
-- expect-output: MECA_STATIQUE: 2 instant\(s\), 1 factorization\(s\).* OK   ANALYTIQUE .*IMPR_RESU: FORMAT='RESULTAT' \(UNITE=8\) written to .*PATCH: every check passed
-- MECA_STATIQUE's patch test. The square [0, 2] x [0, 2] meshed by two distorted QUAD8
-- and four TRIA6 (patch_quad8_tria6.mail), D_PLAN, E = 200, NU = 0.3; DX = 0 on
-- GAUCHE, DY = 0 on BAS, tractions SX on DROITE and SY on HAUT (FORCE_CONTOUR), scaled
-- by FONC_MULT f(t) = t at the instants 0.5 and 1 of LIST_INST. The exact solution is the
-- uniform stress sigma_xx = SX t, sigma_yy = SY t, sigma_xy = 0, sigma_zz = NU (sigma_xx +
-- sigma_yy) (plane strain), with (Hooke, plane strain)
--   u_x = ((1 - NU^2) sigma_xx - NU (1 + NU) sigma_yy) / E x,
--   u_y = ((1 - NU^2) sigma_yy - NU (1 + NU) sigma_xx) / E y,
-- linear, so every element reproduces it exactly on any straight-edged mesh. The
-- reactions on GAUCHE sum to -2 SX t (the traction times DROITE's length). The stiffness
-- is factorized once for both instants. INST alone computes one instant; TEST_RESU and
-- IMPR_RESU read the evol_elas (IMPR_RESU's file is only said written).
local E, NU, SX, SY = 200.0, 0.3, 3.0, -1.25
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol * math.max(1.0, math.abs(b))) then
    error(string.format('%s: %.17g, expected %.17g', what, a, b), 2)
  end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_quad8_tria6.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {{GROUP_MA = 'DROITE', FX = SX}, {GROUP_MA = 'HAUT', FY = SY}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{VALE = {0.5, 1.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR, FONC_MULT = RAMPE}},
                  LIST_INST = L}
xyz = MA:getCoordinates()
local left = {}
for _, n in ipairs(MA:getNodes('GAUCHE')) do left[n] = true end

local function checkInstant(res, t, what)
  local sxx, syy = SX * t, SY * t
  local ex = ((1 - NU * NU) * sxx - NU * (1 + NU) * syy) / E
  local ey = ((1 - NU * NU) * syy - NU * (1 + NU) * sxx) / E
  local u = res:getField('DEPL', t):getValues()
  local r = res:getField('REAC_NODA', t):getValues()
  local reactions = 0.0
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], ex * xyz[3 * n - 2], 1e-10, what .. ': DX of node ' .. n)
    near(u[2 * n], ey * xyz[3 * n - 1], 1e-10, what .. ': DY of node ' .. n)
    if left[n] then reactions = reactions + r[2 * n - 1] end
  end
  near(reactions, -2 * sxx, 1e-10, what .. ': sum of the reactions on GAUCHE')
  local sief = res:getField('SIEF_ELGA', t)
  local cmp = sief:getComponents()
  local v = sief:getValues()
  local exact = {SIXX = sxx, SIYY = syy, SIZZ = NU * (sxx + syy), SIXY = 0.0}
  -- 2 QUAD8 (9 Gauss points) and 4 TRIA6 (at least 3): at least 30 points.
  if #v < 30 * #cmp then error(what .. ': only ' .. #v .. ' SIEF_ELGA values') end
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], exact[c], 1e-10 * math.abs(SX), what .. ': SIEF_ELGA ' .. c .. ' value ' .. i)
  end
end
checkInstant(R, 0.5, 'LIST_INST, INST 0.5')
checkInstant(R, 1.0, 'LIST_INST, INST 1')

RS = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR, FONC_MULT = RAMPE}},
                   INST = 0.5}
checkInstant(RS, 0.5, 'INST 0.5')
if #RS:getAccessParameters().INST ~= 1 then error('INST = 0.5: not one instant') end
-- As in code_aster, MECA_STATIQUE numbers its instants from 1 (STAT_NON_LINE's 0 is the initial state).
local order = R:getAccessParameters().NUME_ORDRE
if #order ~= 2 or order[1] ~= 1 or order[2] ~= 2 then error('NUME_ORDRE of LIST_INST: not 1, 2') end

-- P3 = (2, 2): u_x = 2 ex at t = 1.
local ex1 = ((1 - NU * NU) * SX - NU * (1 + NU) * SY) / E
TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'DEPL', GROUP_NO = 'P3', NOM_CMP = 'DX',
                  VALE_CALC = 2 * ex1, REFERENCE = 'ANALYTIQUE', VALE_REFE = 2 * ex1, PRECISION = 1e-10}}
TEST_RESU{RESU = {RESULTAT = R, NUME_ORDRE = 2, NOM_CHAM = 'DEPL', GROUP_NO = 'P3', NOM_CMP = 'DX',
                  VALE_CALC = 2 * ex1, REFERENCE = 'ANALYTIQUE', VALE_REFE = 2 * ex1, PRECISION = 1e-10}}
IMPR_RESU{FORMAT = 'RESULTAT', RESU = {RESULTAT = R, NOM_CHAM = 'DEPL', INST = 1.0}}
print('PATCH: every check passed')
