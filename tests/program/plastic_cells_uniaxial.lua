-- expect-exit: 0
-- expect-output: PLASTIC CELLS: every check passed
-- The bar of plastic_laws_uniaxial.lua (its closed form, derived there) on every cell
-- type and in both modelisations where a homogeneous uniaxial stress exists: the unit
-- square meshed in TRIA3 (two cells), TRIA6 (two), QUAD4, QUAD8, QUAD9, in C_PLAN
-- (s_zz = 0) and AXIS (the bar along the axis Y: s_rr = s_tt = 0), DY = 0 on BAS,
-- DX = 0 on GAUCHE, DY = e on HAUT: e = 0.004, then -0.002 (reversed plastic flow),
-- one step each. Each of the five von Mises relations; checked at every Gauss point:
-- SIYY, SIXX = SIXY = SIZZ = 0, p (EPSPEQ), XCINYY, INDIPLAS, to 1e-9.
local E, NU, ET, SY, PRAGER = 200000.0, 0.3, 2000.0, 200.0, 1000.0
local H = E * ET / (E - ET)
local e1, e2 = 0.004, -0.002

local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-9 * scale) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

CURVE = DEFI_FONCTION{NOM_PARA = 'EPSI', VALE = {SY / E, SY, SY / E + 0.1, SY + 0.1 * ET}, PROL_DROITE = 'LINEAIRE'}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, ECRO_LINE = {D_SIGM_EPSI = ET, SY = SY}, TRACTION = {SIGM = CURVE},
                    PRAGER = {C = PRAGER}}
EPS = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, e1, 2.0, e2}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0, 2.0}}

-- Per relation: C_t (the back stress is C_t EPSP), and the indices of p, XCINYY and INDIPLAS.
local laws = {
  {name = 'VMIS_ISOT_LINE', C = 0.0, p = 1, plastic = 2},
  {name = 'VMIS_ISOT_TRAC', C = 0.0, p = 1, plastic = 2},
  {name = 'VMIS_CINE_LINE', C = 2.0 / 3.0 * H, p = 8, x = 2, plastic = 7},
  {name = 'VMIS_ECMI_LINE', C = PRAGER, p = 1, x = 4, plastic = 2},
  {name = 'VMIS_ECMI_TRAC', C = PRAGER, p = 1, x = 4, plastic = 2},
}
local unit = 20
for _, cell in ipairs({'tria3', 'tria6', 'quad4', 'quad8', 'quad9'}) do
  unit = unit + 1
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = unit, FICHIER = cell == 'quad4' and 'plastic_square.mail' or 'plastic_' .. cell .. '.mail'}
  local MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = unit}
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  for _, modelisation in ipairs({'C_PLAN', 'AXIS'}) do
    local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = modelisation}}
    local BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
    local PULL = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DY = 1.0}}
    for _, law in ipairs(laws) do
      local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = EPS}},
                              COMPORTEMENT = {RELATION = law.name, RESI_INTE_RELA = 1e-12}, INCREMENT = {LIST_INST = L},
                              CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
      local Ck = 1.5 * law.C
      local Hi = H - Ck
      local p1 = (E * e1 - SY) / (E + H)
      local d = (Ck * p1 - SY - Hi * p1 + E * (p1 - e2)) / (E + H)
      local expected = {
        {t = 1.0, s = SY + H * p1, ep = p1, p = p1},
        {t = 2.0, s = Ck * (p1 - d) - SY - Hi * (p1 + d), ep = p1 - d, p = p1 + d},
      }
      for _, x in ipairs(expected) do
        local sief = R:getField('SIEF_ELGA', x.t):getValues()
        local vari = R:getField('VARI_ELGA', x.t)
        local nv = #vari:getComponents()
        local v = vari:getValues()
        local points = #sief // 4
        assert(points >= 1 and #v == nv * points, 'one value per point')
        for q = 0, points - 1 do
          local what = string.format('%s %s %s at t=%g point %d', cell, modelisation, law.name, x.t, q + 1)
          near(sief[4 * q + 2], x.s, 200.0, what .. ' SIYY')
          near(sief[4 * q + 1], 0.0, 200.0, what .. ' SIXX')
          near(sief[4 * q + 3], 0.0, 200.0, what .. ' SIZZ')
          near(sief[4 * q + 4], 0.0, 200.0, what .. ' SIXY')
          near(v[nv * q + law.p], x.p, 1e-3, what .. ' p')
          near(v[nv * q + law.plastic], 1.0, 1.0, what .. ' INDIPLAS')
          if law.x then near(v[nv * q + law.x], law.C * x.ep, 1.0, what .. ' XCINYY') end
        end
      end
      DETRUIRE{CONCEPT = {NOM = R}}
    end
  end
end
print('PLASTIC CELLS: every check passed')
