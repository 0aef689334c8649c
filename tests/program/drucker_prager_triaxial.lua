-- expect-exit: 0
-- expect-output: DRUCKER-PRAGER TRIAXIAL: every check passed
-- DRUCK_PRAGER and DRUCK_PRAG_N_A through DEFI_MATERIAU and STAT_NON_LINE on one QUAD4 (the
-- unit square, plastic_square.mail), E = 1000, NU = 0.3, ALPHA = A = 0.2, SY = 1.
-- 1. Triaxial compression, AXIS (y the axis): PRES_REP = Pc on DROITE and DX = 0 on the axis,
--    DY = 0 on BAS; on HAUT DY follows the hydrostatic strain -Pc / 3K up to t = 1, then goes
--    down to eps_yy = -0.012 at t = 5. The state is uniform (u_r = c r): s_rr = s_tt = -Pc,
--    s_yy = -Pc - Delta. Closed form (hand-derived): the cone f = q + A I1 - R(p) is reached
--    at Delta_y = (SY + 3 A Pc) / (1 - A); past it (1 - A) Delta - 3 A Pc = R(p) and, the flow
--    direction (1/2 + A, -1 + A, 1/2 + A) being fixed, eps_yy = (s_yy + 2 NU Pc) / E + (A - 1) p.
--    LINEAIRE (R = SY + H p): Delta from eps_yy in closed form. PARABOLIQUE
--    (R = SY (1 - (1 - a) p / P_ULTM)^2, a = sqrt(SY_ULTM / SY)): p from the computed Delta,
--    then eps_yy against the imposed one. EPSPVOL = 3 A p, INDIPLAS = 1.
-- 2. The apex, AXIS: hydrostatic extension eps = e 1 in one step; the return to the apex gives
--    A (9 K e - 9 K A p) = SY + H p, s = (3 K e - 3 K A p) 1, INDIPLAS = 2.
-- 3. DRUCK_PRAG_N_A in D_PLAN (unsymmetric tangent: UMFPACK), a compression: every Gauss
--    point ends on the yield surface, q + A I1 = R(p), with EPSPVOL the integral of
--    3 DILAT (1 - p / P_ULTM) dp taken at the end of each step (bounded here by its exact value).
local E, NU, A, SY, H, PULT = 1000.0, 0.3, 0.2, 1.0, 50.0, 1.0
local K = E / (3 * (1 - 2 * NU))
local Pc = 2.0
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
AX = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
LINE = DEFI_MATERIAU{ELAS = {E = E, NU = NU},
                     DRUCK_PRAGER = {ALPHA = A, SY = SY, P_ULTM = PULT, ECROUISSAGE = 'LINEAIRE', H = H}}
PARA = DEFI_MATERIAU{ELAS = {E = E, NU = NU},
                     DRUCK_PRAGER = {ALPHA = A, SY = SY, P_ULTM = 0.05, ECROUISSAGE = 'PARABOLIQUE', SY_ULTM = 1.6,
                                     DILAT = 0.05}}

-- 1. Triaxial compression.
local e0 = -Pc / (3 * K)
BC = AFFE_CHAR_MECA{MODELE = AX, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
CONF = AFFE_CHAR_MECA{MODELE = AX, PRES_REP = {GROUP_MA = 'DROITE', PRES = Pc}}
AXIAL = AFFE_CHAR_MECA{MODELE = AX, DDL_IMPO = {GROUP_MA = 'HAUT', DY = 1.0}}
RAMP = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0, 5.0, 1.0}}
EYY = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, e0, 5.0, -0.012}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {{JUSQU_A = 1.0, NOMBRE = 1}, {JUSQU_A = 5.0, NOMBRE = 16}}}
local function eyyAt(t) return t <= 1 and e0 * t or e0 + (t - 1) / 4 * (-0.012 - e0) end
local deltaYield = (SY + 3 * A * Pc) / (1 - A)

-- PARABOLIQUE again with ITER_INTE_PAS = -10 (as ssnv168b): a local subdivision only where the
-- local integration fails, which it never does here, so the same closed form holds.
for _, case in ipairs({{name = 'LINEAIRE', mat = LINE, pas = 0}, {name = 'PARABOLIQUE', mat = PARA, pas = 0},
                       {name = 'PARABOLIQUE', mat = PARA, pas = -10}}) do
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = case.mat}}
  local R = STAT_NON_LINE{MODELE = AX, CHAM_MATER = CM,
                          EXCIT = {{CHARGE = BC}, {CHARGE = CONF, FONC_MULT = RAMP}, {CHARGE = AXIAL, FONC_MULT = EYY}},
                          COMPORTEMENT = {RELATION = 'DRUCK_PRAGER', ITER_INTE_PAS = case.pas}, INCREMENT = {LIST_INST = L},
                          CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
  local plastic = 0
  for k = 1, 16 do
    local t = 1 + k / 4
    local eyy = eyyAt(t)
    local s = R:getField('SIEF_ELGA', t):getValues()
    local v = R:getField('VARI_ELGA', t):getValues()
    for q = 0, 3 do
      local what = case.name .. ' t=' .. t .. ' point ' .. (q + 1)
      near(s[4 * q + 1], -Pc, 1e-9, what .. ' SIXX')
      near(s[4 * q + 3], -Pc, 1e-9, what .. ' SIZZ')
      local syy = s[4 * q + 2]
      local delta = -syy - Pc
      local p
      if case.name == 'LINEAIRE' then
        -- eps_yy = (-Pc - Delta + 2 NU Pc) / E + (A - 1) ((1 - A) Delta - 3 A Pc - SY) / H
        local expected = (eyy + Pc * (1 - 2 * NU) / E + (A - 1) * (3 * A * Pc + SY) / H) / (-1 / E - (1 - A) ^ 2 / H)
        if expected < deltaYield then expected = -(eyy + Pc * (1 - 2 * NU) / E) * E end
        near(delta, expected, 1e-9, what .. ' Delta')
        p = math.max(0, ((1 - A) * delta - 3 * A * Pc - SY) / H)
      else
        local a = math.sqrt(1.6 / SY)
        local R = (1 - A) * delta - 3 * A * Pc
        p = R > SY * (1 + 1e-12) and 0.05 * (1 - math.sqrt(R / SY)) / (1 - a) or 0.0
        near(eyy, (syy + 2 * NU * Pc) / E + (A - 1) * p, 1e-12, what .. ' EPYY')
      end
      near(v[3 * q + 1], p, 1e-10, what .. ' EPSPEQ')
      near(v[3 * q + 2], 3 * A * p, 1e-10, what .. ' EPSPVOL')
      if p > 1e-9 then
        near(v[3 * q + 3], 1.0, 0.0, what .. ' INDIPLAS')
        plastic = plastic + 1
      end
    end
  end
  if plastic < 40 then error(case.name .. ': only ' .. plastic .. ' plastic points') end
end

-- 2. The apex: hydrostatic extension e = 0.01 in one step.
local e = 0.01
SWELL = AFFE_CHAR_MECA{MODELE = AX, DDL_IMPO = {{GROUP_MA = 'DROITE', DX = e}, {GROUP_MA = 'HAUT', DY = e}}}
CM1 = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = LINE}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
RA = STAT_NON_LINE{MODELE = AX, CHAM_MATER = CM1, EXCIT = {{CHARGE = BC}, {CHARGE = SWELL}},
                   COMPORTEMENT = {RELATION = 'DRUCK_PRAGER'}, INCREMENT = {LIST_INST = L1},
                   CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
local p = (9 * K * A * e - SY) / (9 * K * A * A + H)
local mean = 3 * K * e - 3 * K * A * p
local s = RA:getField('SIEF_ELGA', 1.0):getValues()
local v = RA:getField('VARI_ELGA', 1.0):getValues()
for q = 0, 3 do
  local what = 'apex point ' .. (q + 1)
  for c = 1, 3 do near(s[4 * q + c], mean, 1e-9 * mean, what .. ' SI' .. c) end
  near(s[4 * q + 4], 0.0, 1e-9 * mean, what .. ' SIXY')
  near(v[3 * q + 1], p, 1e-12, what .. ' EPSPEQ')
  near(v[3 * q + 2], 3 * A * p, 1e-12, what .. ' EPSPVOL')
  near(v[3 * q + 3], 2.0, 0.0, what .. ' INDIPLAS')
end

-- 3. DRUCK_PRAG_N_A in D_PLAN: a compression with a non-uniform top displacement.
DP = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
BC2 = AFFE_CHAR_MECA{MODELE = DP, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
PRESS = AFFE_CHAR_MECA_F{MODELE = DP, DDL_IMPO = {GROUP_MA = 'HAUT', DY = FORMULE{NOM_PARA = {'X', 'INST'}, VALE = '-0.002 * INST * (1 + 0.5 * X)'}}}
CM2 = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = PARA}}
L3 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 3.0, NOMBRE = 6}}
RN = STAT_NON_LINE{MODELE = DP, CHAM_MATER = CM2, EXCIT = {{CHARGE = BC2}, {CHARGE = PRESS}},
                   COMPORTEMENT = {RELATION = 'DRUCK_PRAG_N_A'}, INCREMENT = {LIST_INST = L3},
                   CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
local s3 = RN:getField('SIEF_ELGA', 3.0):getValues()
local v3 = RN:getField('VARI_ELGA', 3.0):getValues()
local a = math.sqrt(1.6 / SY)
for q = 0, 3 do
  local what = 'DRUCK_PRAG_N_A point ' .. (q + 1)
  local xx, yy, zz, xy = s3[4 * q + 1], s3[4 * q + 2], s3[4 * q + 3], s3[4 * q + 4]
  local m = (xx + yy + zz) / 3
  local qeq = math.sqrt(1.5 * ((xx - m) ^ 2 + (yy - m) ^ 2 + (zz - m) ^ 2 + 2 * xy * xy))
  local pq = v3[3 * q + 1]
  if not (pq > 1e-3) then error(what .. ': p = ' .. pq .. ', expected plastic') end
  local Rp = SY * (1 - (1 - a) * math.min(pq, 0.05) / 0.05) ^ 2
  near(qeq + A * 3 * m, Rp, 1e-10, what .. ' on the yield surface')
  near(v3[3 * q + 3], 1.0, 0.0, what .. ' INDIPLAS')
  -- EPSPVOL lies between the exact integral and its value with B(p) at the start.
  local pe = math.min(pq, 0.05)
  local exact = 3 * 0.05 * (pe - pe * pe / (2 * 0.05))
  if not (v3[3 * q + 2] > 0 and v3[3 * q + 2] <= exact * (1 + 1e-12)) then
    error(what .. ': EPSPVOL = ' .. v3[3 * q + 2] .. ', exact integral ' .. exact)
  end
end
print('DRUCKER-PRAGER TRIAXIAL: every check passed')
