-- expect-exit: 0
-- expect-output: NEWTON OPTIONS: every check passed.*<A> <STAT_NON_LINE> instant 1\.000000E-01: no convergence in ITER_GLOB_MAXI = 1 Newton iterations \(RESI_GLOB_RELA = [0-9.E+-]+\); the step is accepted as it is \(CONVERGENCE/ARRET='NON'\)
-- NEWTON and CONVERGENCE keywords of STAT_NON_LINE, on a nonlinear case with an
-- exact solution. The unit square (one QUAD4), D_PLAN, GROT_GDEP (Saint
-- Venant-Kirchhoff), E = 200, NU = 0.3; DX = 0 on GAUCHE, DY = 0 on BAS, and
-- DX = a t on DROITE (a = 0.4, ten steps up to t = 1): a homogeneous stretch
-- x = l1 X, y = l2 Y with l1 = 1 + a t, E11 = (l1^2 - 1) / 2, and the free top
-- (S22 = 0) gives E22 = -NU / (1 - NU) E11, l2 = sqrt(1 + 2 E22).
-- 1. PREDICTION = 'TANGENTE' (the default), 'EXTRAPOLE', 'ELASTIQUE': the same
--    converged solution (the exact one, to the tolerance); EXTRAPOLE, which starts
--    each step from U_n + (dt_n+1 / dt_n)(U_n - U_n-1), takes no more iterations than
--    TANGENTE at any instant, and fewer in all; the first step has no previous
--    increment and is a TANGENTE one.
-- 2. MATRICE = 'ELASTIQUE': converges to the same solution in more iterations.
-- 3. REAC_INCR: with REAC_ITER = 0, the prediction's tangent reassembled at each
--    step (REAC_INCR = 1) against never after the first (REAC_INCR = 0): same
--    solution, more iterations without.
-- 4. RESI_GLOB_MAXI = 1e-3 alone: every step stops at its second iteration, when the
--    largest residual (REAC_NODA at the free DOFs) drops below 1e-3 (its first
--    is near 7e-2, its second near 1e-4); with RESI_GLOB_RELA = 1e-10 as well,
--    both must hold: three iterations.
-- 5. ARRET = 'NON' with ITER_GLOB_MAXI = 1: every step is accepted after one
--    iteration, with an alarm (header of this file: alarms go to stderr), and stored.
local E, NU, a = 200.0, 0.3, 0.4
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, x, y), 2)
  end
end
local function exact(t)
  local l1 = 1 + a * t
  local E11 = (l1 * l1 - 1) / 2
  return l1, math.sqrt(1 - 2 * NU / (1 - NU) * E11)
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
ST = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'DROITE', DX = a}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
xyz = MA:getCoordinates()

local function run(newton, convergence)
  return STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = ST, FONC_MULT = RAMPE}},
                       COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, NEWTON = newton,
                       CONVERGENCE = convergence or {RESI_GLOB_RELA = 1e-10, ITER_GLOB_MAXI = 100},
                       INCREMENT = {LIST_INST = L}}
end
local function checkExact(R, tol, what)
  for _, t in ipairs(R:getAccessParameters().INST) do
    local l1, l2 = exact(t)
    local u = R:getField('DEPL', t):getValues()
    for n = 1, MA:getNumberOfNodes() do
      near(u[2 * n - 1], (l1 - 1) * xyz[3 * n - 2], tol, string.format('%s: DX of node %d at INST %g', what, n, t))
      near(u[2 * n], (l2 - 1) * xyz[3 * n - 1], tol, string.format('%s: DY of node %d at INST %g', what, n, t))
    end
  end
end
local function iterations(R)
  local it, total = R:getAccessParameters().ITER_GLOB, 0
  assert(#it == 11, 'eleven instants expected, got ' .. #it)
  for i = 2, #it do total = total + it[i] end
  return it, total
end

-- 1. PREDICTION.
local RT, RX, RE = run({PREDICTION = 'TANGENTE'}), run({PREDICTION = 'EXTRAPOLE'}), run({PREDICTION = 'ELASTIQUE'})
checkExact(RT, 1e-9, 'PREDICTION=TANGENTE')
checkExact(RX, 1e-9, 'PREDICTION=EXTRAPOLE')
checkExact(RE, 1e-9, 'PREDICTION=ELASTIQUE')
local itT, totalT = iterations(RT)
local itX, totalX = iterations(RX)
for i = 2, #itT do
  assert(itX[i] <= itT[i], string.format('EXTRAPOLE took %d iterations at instant %d, TANGENTE %d', itX[i], i - 1, itT[i]))
end
assert(itX[2] == itT[2], 'the first step has nothing to extrapolate from: a TANGENTE prediction')
assert(totalX < totalT, string.format('EXTRAPOLE: %d iterations in all, TANGENTE %d', totalX, totalT))

-- 2. MATRICE = 'ELASTIQUE'.
local RM = run({MATRICE = 'ELASTIQUE'})
checkExact(RM, 1e-9, 'MATRICE=ELASTIQUE')
local _, totalM = iterations(RM)
assert(totalM > totalT, string.format('MATRICE=ELASTIQUE: %d iterations in all, TANGENTE %d', totalM, totalT))

-- 3. REAC_INCR.
local R1, R0 = run({REAC_ITER = 0, REAC_INCR = 1}), run({REAC_ITER = 0, REAC_INCR = 0})
checkExact(R1, 1e-9, 'REAC_ITER=0, REAC_INCR=1')
checkExact(R0, 1e-9, 'REAC_ITER=0, REAC_INCR=0')
local _, total1 = iterations(R1)
local _, total0 = iterations(R0)
assert(total0 > total1, string.format('REAC_INCR=0: %d iterations in all, REAC_INCR=1 %d', total0, total1))

-- 4. RESI_GLOB_MAXI, alone and with RESI_GLOB_RELA.
local RA = run(nil, {RESI_GLOB_MAXI = 1e-3})
checkExact(RA, 1e-5, 'RESI_GLOB_MAXI=1e-3')
local itA = iterations(RA)
local bottom, top = {}, {}
for _, n in ipairs(MA:getNodes('BAS')) do bottom[n] = true end
for _, n in ipairs(MA:getNodes('GAUCHE')) do top[n] = true end  -- DX held
for _, n in ipairs(MA:getNodes('DROITE')) do top[n] = true end  -- DX imposed
for i, t in ipairs(RA:getAccessParameters().INST) do
  if i > 1 then
    assert(itA[i] == 2, string.format('RESI_GLOB_MAXI=1e-3: %d iterations at INST %g, expected 2', itA[i], t))
    local r = RA:getField('REAC_NODA', t):getValues()
    for n = 1, MA:getNumberOfNodes() do
      if not top[n] then near(r[2 * n - 1], 0.0, 1e-3, string.format('residual DX of node %d at INST %g', n, t)) end
      if not bottom[n] then near(r[2 * n], 0.0, 1e-3, string.format('residual DY of node %d at INST %g', n, t)) end
    end
  end
end
local RB = run(nil, {RESI_GLOB_MAXI = 1e-3, RESI_GLOB_RELA = 1e-10})
checkExact(RB, 1e-9, 'RESI_GLOB_MAXI=1e-3 and RESI_GLOB_RELA=1e-10')
local itB = iterations(RB)
for i = 2, #itB do assert(itB[i] == 3, 'both criteria: ' .. itB[i] .. ' iterations at instant ' .. i - 1) end

-- 5. ARRET = 'NON'.
local RN = run(nil, {ITER_GLOB_MAXI = 1, ARRET = 'NON'})
local itN = iterations(RN)
for i = 2, #itN do assert(itN[i] == 1, 'ARRET=NON: ' .. itN[i] .. ' iterations at instant ' .. i - 1) end
print('NEWTON OPTIONS: every check passed')
