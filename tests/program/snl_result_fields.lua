-- expect-exit: 0
-- expect-output: iter  RESI_GLOB_RELA   RESI_GLOB_MAXI   matrix      time \(s\).*       0  [0-9.E+-]+     [0-9.E+-]+         TANGENTE    [0-9]\.[0-9][0-9]E[-+][0-9]+ .*       1  [0-9.E+-]+     [0-9.E+-]+                     [0-9]\.[0-9][0-9]E[-+][0-9]+ .*RESULT FIELDS: every check passed
-- STAT_NON_LINE's result fields at command level, against the exact solution.
-- The unit square (one QUAD4, then one QUAD8), PETIT, D_PLAN, E = 200, NU = 0.3,
-- DX = 0 on GAUCHE, DY = 0 at P1 = (0, 0), a dead traction (p f(t), 0) on DROITE
-- with f(t) = t, instants 0, 0.5, 1. The exact solution is a uniform stress
-- sigma_xx = p t, sigma_yy = sigma_xy = 0, sigma_zz = NU p t (plane strain), and
--   u_x = (1 - NU^2) / E p t x,   u_y = -NU (1 + NU) / E p t y,
-- which both elements reproduce exactly. By hand, FORC_NODA_a = int sigma grad N_a
-- = p t (int_DROITE N_a - int_GAUCHE N_a) e_x: QUAD4 +-p t/2 at the corners of
-- DROITE / GAUCHE; QUAD8 +-p t/6 at the corners and +-2 p t/3 at the middle nodes of
-- DROITE / GAUCHE, 0 at the middles of BAS and HAUT; DY 0 everywhere. At the free
-- DOFs FORC_NODA equals the applied nodal loads, at the supports it equals
-- REAC_NODA (no load there); REAC_NODA sums to -p t (the applied force), FORC_NODA
-- to 0, and REAC_NODA vanishes (residual) at the free DOFs. The convergence table
-- has the time of each iteration (header above).
local E, NU, p = 200.0, 0.3, 2.0
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, a, b), 2)
  end
end

local function check(unit, file, gaussPoints, forcNoda)
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = unit, FICHIER = file}
  local MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = unit}
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
  local MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  local BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
  local TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = p}}
  local RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
  local L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM,
                          EXCIT = {{CHARGE = BC}, {CHARGE = TR, FONC_MULT = RAMPE}},
                          COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'},
                          INCREMENT = {LIST_INST = L}}

  local access = R:getAccessParameters()
  assert(#access.INST == 3 and #access.NUME_ORDRE == 3, file .. ': three instants expected')
  for i, t in ipairs({0.0, 0.5, 1.0}) do
    near(access.INST[i], t, 1e-15, file .. ' INST[' .. i .. ']')
    assert(access.NUME_ORDRE[i] == i - 1, file .. ': NUME_ORDRE')
  end
  assert(access.ITER_GLOB[1] == 0 and access.ITER_GLOB[3] == 1, file .. ': a linear step takes one iteration')

  local xyz = MA:getCoordinates()
  local nodes = MA:getNumberOfNodes()
  local left, fixedDY = {}, {}
  for _, n in ipairs(MA:getNodes('GAUCHE')) do left[n] = true end
  for _, n in ipairs(MA:getNodes('P1')) do fixedDY[n] = true end
  for _, t in ipairs({0.5, 1.0}) do
    local where = string.format('%s at INST %g', file, t)
    local sxx = p * t
    -- DEPL: node after node, DX then DY, the exact linear solution.
    local depl = R:getField('DEPL', t)
    local c = depl:getComponents()
    assert(#c == 2 and c[1] == 'DX' and c[2] == 'DY', where .. ': DEPL components')
    local u = depl:getValues()
    assert(#u == 2 * nodes, where .. ': DEPL has 2 values per node')
    for n = 1, nodes do
      local x, y = xyz[3 * n - 2], xyz[3 * n - 1]
      near(u[2 * n - 1], (1 - NU * NU) / E * sxx * x, 1e-14, where .. ' DX of node ' .. n)
      near(u[2 * n], -NU * (1 + NU) / E * sxx * y, 1e-14, where .. ' DY of node ' .. n)
    end
    -- SIEF_ELGA: cell after cell, Gauss point after Gauss point, SIXX SIYY SIZZ SIXY.
    local sief = R:getField('SIEF_ELGA', t)
    c = sief:getComponents()
    assert(#c == 4 and c[1] == 'SIXX' and c[2] == 'SIYY' and c[3] == 'SIZZ' and c[4] == 'SIXY', where .. ': SIEF_ELGA components')
    local s = sief:getValues()
    assert(#s == 4 * gaussPoints, where .. ': ' .. #s .. ' SIEF_ELGA values, expected 4 per Gauss point')
    for g = 0, gaussPoints - 1 do
      near(s[4 * g + 1], sxx, 1e-12, where .. ' SIXX at Gauss point ' .. g + 1)
      near(s[4 * g + 2], 0.0, 1e-12, where .. ' SIYY at Gauss point ' .. g + 1)
      near(s[4 * g + 3], NU * sxx, 1e-12, where .. ' SIZZ at Gauss point ' .. g + 1)
      near(s[4 * g + 4], 0.0, 1e-12, where .. ' SIXY at Gauss point ' .. g + 1)
    end
    -- FORC_NODA against the hand values; REAC_NODA at the supports and elsewhere.
    local f = R:getField('FORC_NODA', t):getValues()
    local r = R:getField('REAC_NODA', t):getValues()
    local fsum, fsumy, rsum = 0.0, 0.0, 0.0
    for n = 1, nodes do
      near(f[2 * n - 1], forcNoda[n] * t, 1e-12, where .. ' FORC_NODA DX of node ' .. n)
      near(f[2 * n], 0.0, 1e-12, where .. ' FORC_NODA DY of node ' .. n)
      fsum, fsumy = fsum + f[2 * n - 1], fsumy + f[2 * n]
      if left[n] then
        near(r[2 * n - 1], f[2 * n - 1], 1e-12, where .. ' REAC_NODA DX of node ' .. n)
        rsum = rsum + r[2 * n - 1]
      else
        near(r[2 * n - 1], 0.0, 1e-12, where .. ' REAC_NODA DX (residual) of node ' .. n)
      end
      if not fixedDY[n] then near(r[2 * n], 0.0, 1e-12, where .. ' REAC_NODA DY (residual) of node ' .. n) end
    end
    near(fsum, 0.0, 1e-12, where .. ' sum of FORC_NODA DX')
    near(fsumy, 0.0, 1e-12, where .. ' sum of FORC_NODA DY')
    near(rsum, -p * t, 1e-12, where .. ' sum of REAC_NODA DX over GAUCHE')
  end
  -- The initial state holds zero fields too.
  for _, v in ipairs(R:getField('SIEF_ELGA', 0.0):getValues()) do near(v, 0.0, 0.0, file .. ' SIEF_ELGA at INST 0') end
end

-- QUAD4: nodes N1 (0,0), N2 (1,0), N3 (1,1), N4 (0,1); 2 x 2 Gauss points.
check(20, 'square_quad4.mail', 4, {-p / 2, p / 2, p / 2, -p / 2})
-- QUAD8: then the middles N5 (BAS), N6 (DROITE), N7 (HAUT), N8 (GAUCHE); 3 x 3 Gauss points.
check(21, 'square_quad8.mail', 9, {-p / 6, p / 6, p / 6, -p / 6, 0.0, 2 * p / 3, 0.0, -2 * p / 3})
print('RESULT FIELDS: every check passed')
