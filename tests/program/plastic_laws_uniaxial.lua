-- expect-exit: 0
-- expect-output: PLASTIC LAWS: every check passed
-- Each von Mises relation of COMPORTEMENT through DEFI_MATERIAU and STAT_NON_LINE, on one
-- QUAD4 (plastic_square.mail) in plane stress, pulled along Y (DY = 0 on BAS, DX = 0 on
-- GAUCHE, DY = e on HAUT): e = 0.004 in one step, then e = -0.002 in one step (reversed
-- plastic flow: the Bauschinger effect of the kinematic part). E = 200000, NU = 0.3,
-- the uniaxial curve of slope ET = 2000 past SY = 200 (ECRO_LINE, or TRACTION through
-- the points (SY/E, SY), (SY/E + 0.1, SY + 0.1 ET) with PROL_DROITE='LINEAIRE'); PRAGER
-- C = 1000 for the mixed laws. Closed form, derived by hand for uniaxial stress s with
-- the signed plastic strain ep (EPSP = ep (-1/2, 1, -1/2)) and p the cumulated one:
-- the back stress is X = C_t EPSP (C_t = 2/3 H for VMIS_CINE_LINE, PRAGER's C for the mixed
-- laws, 0 for the isotropic ones), so that yield reads |s - Ck ep| = R(p), Ck = 3/2 C_t,
-- R(p) = SY + Hi p, Hi = H - Ck, H = E ET / (E - ET) (the monotonic curve is the same for
-- every law). Loading: p1 = ep1 = (E e1 - SY) / (E + H), s1 = SY + H p1. Reversed step
-- (compression, e2 = -0.002): ep = ep1 - d, p = p1 + d with
-- d = (Ck ep1 - SY - Hi p1 + E (ep1 - e2)) / (E + H), s2 = Ck ep - SY - Hi p.
-- Checked: SIYY, p (EPSPEQ), XCINYY = C_t ep, INDIPLAS, at every Gauss point.
local E, NU, ET, SY, PRAGER = 200000.0, 0.3, 2000.0, 200.0, 1000.0
local H = E * ET / (E - ET)
local e1, e2 = 0.004, -0.002

local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-9 * scale) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
CURVE = DEFI_FONCTION{NOM_PARA = 'EPSI', VALE = {SY / E, SY, SY / E + 0.1, SY + 0.1 * ET}, PROL_DROITE = 'LINEAIRE'}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, ECRO_LINE = {D_SIGM_EPSI = ET, SY = SY}, TRACTION = {SIGM = CURVE},
                    PRAGER = {C = PRAGER}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DY = 1.0}}
EPS = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, e1, 2.0, e2}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0, 2.0}}

-- Per relation: C_t, and the indices of p, XCINYY and INDIPLAS among its variables.
local laws = {
  VMIS_ISOT_LINE = {C = 0.0, p = 1, plastic = 2},
  VMIS_ISOT_TRAC = {C = 0.0, p = 1, plastic = 2},
  VMIS_CINE_LINE = {C = 2.0 / 3.0 * H, p = 8, x = 2, plastic = 7},
  VMIS_ECMI_LINE = {C = PRAGER, p = 1, x = 4, plastic = 2},
  VMIS_ECMI_TRAC = {C = PRAGER, p = 1, x = 4, plastic = 2},
}
for relation, law in pairs(laws) do
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = EPS}},
                          COMPORTEMENT = {RELATION = relation, RESI_INTE_RELA = 1e-12}, INCREMENT = {LIST_INST = L},
                          CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
  local Ck = 1.5 * law.C
  local Hi = H - Ck
  local p1 = (E * e1 - SY) / (E + H)
  local d = (Ck * p1 - SY - Hi * p1 + E * (p1 - e2)) / (E + H)
  local expected = {
    [1.0] = {s = SY + H * p1, ep = p1, p = p1},
    [2.0] = {s = Ck * (p1 - d) - SY - Hi * (p1 + d), ep = p1 - d, p = p1 + d},
  }
  for t, x in pairs(expected) do
    local sief = R:getField('SIEF_ELGA', t):getValues()
    local vari = R:getField('VARI_ELGA', t)
    local nv = #vari:getComponents()
    local v = vari:getValues()
    for q = 0, 3 do
      local what = relation .. ' at t=' .. t .. ' point ' .. (q + 1)
      near(sief[4 * q + 2], x.s, 200.0, what .. ' SIYY')
      near(sief[4 * q + 1], 0.0, 200.0, what .. ' SIXX')
      near(v[nv * q + law.p], x.p, 1e-3, what .. ' p')
      near(v[nv * q + law.plastic], 1.0, 1.0, what .. ' INDIPLAS')
      if law.x then near(v[nv * q + law.x], law.C * x.ep, 1.0, what .. ' XCINYY') end
    end
  end
end
print('PLASTIC LAWS: every check passed')
