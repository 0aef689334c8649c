-- expect-exit: 0
-- expect-output: MODELISATIONS: every check passed
-- AXIS and C_PLAN through the commands (AFFE_MODELE, AFFE_CHAR_MECA, MECA_STATIQUE,
-- STAT_NON_LINE, SIEF_ELGA, REAC_NODA, FORC_NODA). The distorted QUAD8/TRIA6 patch of
-- [0, 2] x [0, 2] (patch_quad8_tria6.mail), E = 200, NU = 0.3.
-- 1. AXIS (r = X, the axis X = 0 touches GAUCHE): FORCE_CONTOUR FX = S on DROITE
--    (r = 2) and FY = T on HAUT, DY = 0 on BAS, nothing on the axis. The exact
--    solution is the uniform stress s_rr = s_tt = S, s_zz = T (equilibrium:
--    d s_rr/dr + (s_rr - s_tt)/r = 0), u_r = a r, u_z = b z with (Hooke in 3D)
--    a = ((1 - NU) S - NU T)/E, b = (T - 2 NU S)/E, reproduced by every element.
--    Per radian: the reactions on BAS sum to -T int_0^2 r dr = -2 T; FORC_NODA's DX on
--    DROITE sums to S * 2 * 2 (the load per radian, r = 2, height 2). By MECA_STATIQUE
--    and by STAT_NON_LINE PETIT (one Newton iteration, the same numbers).
-- 2. C_PLAN, MECA_STATIQUE: tractions SX on DROITE, SY on HAUT; SIZZ = 0, plane stress
--    Hooke u_x = (SX - NU SY)/E x.
-- 3. C_PLAN, STAT_NON_LINE GROT_GDEP: DX = d on DROITE, DX = 0 on GAUCHE, DY = 0 on
--    BAS: the homogeneous uniaxial state of Saint Venant-Kirchhoff in plane stress,
--    E11 = ((1 + d)^2 - 1)/2, S11 = E E11, S22 = S33 = 0, E22 = -NU E11 (from S22 = 0
--    and S33 = 0), so u_y = (sqrt(1 + 2 E22) - 1) y. SIEF_ELGA is the Cauchy stress
--    F S F^T / J (as code_aster), F = diag(1 + d, m, m), m = sqrt(1 - 2 NU E11):
--    SIXX = (1 + d)^2 S11 / ((1 + d) m^2) = (1 + d) E E11 / m^2.
local E, NU = 200.0, 0.3
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_quad8_tria6.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
local xyz = MA:getCoordinates()
local function nodeSet(group)
  local set = {}
  for _, n in ipairs(MA:getNodes(group)) do set[n] = true end
  return set
end
local bottom, right = nodeSet('BAS'), nodeSet('DROITE')

local function checkSief(res, t, exact, what)
  local sief = res:getField('SIEF_ELGA', t)
  local cmp, v = sief:getComponents(), sief:getValues()
  if #v < 30 * #cmp then error(what .. ': only ' .. #v .. ' SIEF_ELGA values') end
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], exact[c], 1e-10, what .. ': SIEF_ELGA ' .. c .. ' value ' .. i)
  end
end

-- 1. AXIS
local S, T = 3.0, -1.25
local a, b = ((1 - NU) * S - NU * T) / E, (T - 2 * NU * S) / E
MOA = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
BCA = AFFE_CHAR_MECA{MODELE = MOA, DDL_IMPO = {GROUP_MA = 'BAS', DY = 0.0}}
TRA = AFFE_CHAR_MECA{MODELE = MOA, FORCE_CONTOUR = {{GROUP_MA = 'DROITE', FX = S}, {GROUP_MA = 'HAUT', FY = T}}}
RA = MECA_STATIQUE{MODELE = MOA, CHAM_MATER = CM, EXCIT = {{CHARGE = BCA}, {CHARGE = TRA}}, INST = 1.0}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
NA = STAT_NON_LINE{MODELE = MOA, CHAM_MATER = CM, EXCIT = {{CHARGE = BCA}, {CHARGE = TRA}},
                   COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L1},
                   CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
for _, case in ipairs({{RA, 'AXIS MECA_STATIQUE'}, {NA, 'AXIS STAT_NON_LINE'}}) do
  local res, what = case[1], case[2]
  local u, r = res:getField('DEPL', 1.0):getValues(), res:getField('REAC_NODA', 1.0):getValues()
  local f = res:getField('FORC_NODA', 1.0):getValues()
  local reaction, inner = 0.0, 0.0
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], a * xyz[3 * n - 2], 1e-12, what .. ': DX of node ' .. n)
    near(u[2 * n], b * xyz[3 * n - 1], 1e-12, what .. ': DY of node ' .. n)
    if bottom[n] then reaction = reaction + r[2 * n] end
    if right[n] then inner = inner + f[2 * n - 1] end
  end
  near(reaction, -2 * T, 1e-10, what .. ': sum of the reactions per radian on BAS')
  near(inner, 4 * S, 1e-10, what .. ': sum of FORC_NODA DX per radian on DROITE')
  checkSief(res, 1.0, {SIXX = S, SIYY = T, SIZZ = S, SIXY = 0.0}, what)
end

-- 2. C_PLAN, small strain
local SX, SY = 2.0, 0.5
MOC = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
BCC = AFFE_CHAR_MECA{MODELE = MOC, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
TRC = AFFE_CHAR_MECA{MODELE = MOC, FORCE_CONTOUR = {{GROUP_MA = 'DROITE', FX = SX}, {GROUP_MA = 'HAUT', FY = SY}}}
RC = MECA_STATIQUE{MODELE = MOC, CHAM_MATER = CM, EXCIT = {{CHARGE = BCC}, {CHARGE = TRC}}}
local uc = RC:getField('DEPL', 0.0):getValues()
for n = 1, MA:getNumberOfNodes() do
  near(uc[2 * n - 1], (SX - NU * SY) / E * xyz[3 * n - 2], 1e-12, 'C_PLAN: DX of node ' .. n)
  near(uc[2 * n], (SY - NU * SX) / E * xyz[3 * n - 1], 1e-12, 'C_PLAN: DY of node ' .. n)
end
checkSief(RC, 0.0, {SIXX = SX, SIYY = SY, SIZZ = 0.0, SIXY = 0.0}, 'C_PLAN MECA_STATIQUE')

-- 3. C_PLAN, GROT_GDEP
local d = 0.3
BCG = AFFE_CHAR_MECA{MODELE = MOC, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0},
                                                {GROUP_MA = 'DROITE', DX = 2 * d}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L2 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {{JUSQU_A = 1.0, NOMBRE = 2}}}
NG = STAT_NON_LINE{MODELE = MOC, CHAM_MATER = CM, EXCIT = {{CHARGE = BCG, FONC_MULT = RAMPE}},
                   COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, INCREMENT = {LIST_INST = L2},
                   CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
local E11 = ((1 + d) ^ 2 - 1) / 2
local m = math.sqrt(1 - 2 * NU * E11)
local ug = NG:getField('DEPL', 1.0):getValues()
for n = 1, MA:getNumberOfNodes() do
  near(ug[2 * n - 1], d * xyz[3 * n - 2], 1e-12, 'C_PLAN GROT_GDEP: DX of node ' .. n)
  near(ug[2 * n], (m - 1) * xyz[3 * n - 1], 1e-10, 'C_PLAN GROT_GDEP: DY of node ' .. n)
end
checkSief(NG, 1.0, {SIXX = (1 + d) * E * E11 / (m * m), SIYY = 0.0, SIZZ = 0.0, SIXY = 0.0}, 'C_PLAN GROT_GDEP')
print('MODELISATIONS: every check passed')
