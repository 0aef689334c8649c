-- expect-exit: 0
-- expect-output: GDEF_LOG: every check passed
-- STAT_NON_LINE with COMPORTEMENT DEFORMATION = 'GDEF_LOG' and ELAS: the Hencky
-- material, tau = lambda tr(T) I + 2 mu T on the logarithmic strain T (tau = J sigma).
-- The distorted 2 x 2 QUAD4 patch of [0, 2]^2, D_PLAN, E = 200, NU = 0.3; DX = 0 on
-- GAUCHE, DY = 0 on BAS, DX = a t on DROITE (a = 0.8: a stretch of 1.4 in one step),
-- HAUT free: the homogeneous stretch x = l1 X, y = l2 Y, l1 = 1 + a t / 2, with
-- sigma_yy = 0: ln l2 = -NU / (1 - NU) ln l1, and by hand
--   tau_xx = E / (1 - NU^2) ln l1, sigma_xx = tau_xx / (l1 l2), sigma_zz = NU sigma_xx,
-- the internal variables V1..V6 = TXX, TYY, TZZ, TXY, TXZ, TYZ = the stress tau
-- (T = diag(ln l1, ln l2, 0) in the frame of the stretch).
-- 1. Two steps: displacements, SIEF_ELGA (Cauchy) and VARI_ELGA against the above.
-- 2. Newton's convergence with the consistent tangent is quadratic: with ARRET='NON'
--    and ITER_GLOB_MAXI = k, the step stops after k iterations; the largest residual
--    (REAC_NODA at the free DOFs) r_k of k = 1 ... 4 keeps r_k+1 / r_k^2 near a
--    constant C, with C r_1 well below 1 (a linear rate would keep r_k+1 / r_k near a
--    constant instead, and r_k+1 / r_k^2 would grow as r_k falls).
-- 3. C_PLAN and AXIS in uniaxial stress (described at the end).
local E, NU, a = 200.0, 0.3, 0.8
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, x, y), 2)
  end
end
local function exact(t)
  local l1 = 1 + a * t / 2
  local t1 = math.log(l1)
  local t2 = -NU / (1 - NU) * t1
  return l1, math.exp(t2), t1, t2
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
ST = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'DROITE', DX = a}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
local xyz = MA:getCoordinates()

local function run(list, convergence)
  return STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = ST, FONC_MULT = RAMPE}},
                       COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GDEF_LOG'},
                       CONVERGENCE = convergence, INCREMENT = {LIST_INST = list}}
end

-- 1. The converged solution.
L2 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
R = run(L2, {RESI_GLOB_RELA = 1e-12, ITER_GLOB_MAXI = 20})
for _, t in ipairs({0.5, 1.0}) do
  local l1, l2, t1, t2 = exact(t)
  local u = R:getField('DEPL', t):getValues()
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], (l1 - 1) * xyz[3 * n - 2], 1e-10, string.format('DX of node %d at INST %g', n, t))
    near(u[2 * n], (l2 - 1) * xyz[3 * n - 1], 1e-10, string.format('DY of node %d at INST %g', n, t))
  end
  local tau = E / (1 - NU * NU) * t1
  local sxx = tau / (l1 * l2)
  local sief = R:getField('SIEF_ELGA', t)
  local cmp, v = sief:getComponents(), sief:getValues()
  local cauchy = {SIXX = sxx, SIYY = 0.0, SIZZ = NU * sxx, SIXY = 0.0}
  for i = 1, #v do
    local k = cmp[(i - 1) % #cmp + 1]
    near(v[i], cauchy[k], 1e-9 * sxx, string.format('SIEF_ELGA %s value %d at INST %g', k, i, t))
  end
  local vari = R:getField('VARI_ELGA', t)
  local vcmp, vv = vari:getComponents(), vari:getValues()
  assert(#vcmp == 6, 'VARI_ELGA: 6 components expected (TXX ... TYZ), got ' .. #vcmp)
  local dual = {V1 = tau, V2 = 0.0, V3 = NU * tau, V4 = 0.0, V5 = 0.0, V6 = 0.0}
  for i = 1, #vv do
    local k = vcmp[(i - 1) % #vcmp + 1]
    near(vv[i], dual[k], 1e-9 * tau, string.format('VARI_ELGA %s value %d at INST %g', k, i, t))
  end
end

-- 2. The residual after k Newton iterations of one step to t = 1.
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
local held = {}  -- [node] = {DX held, DY held}
for n = 1, MA:getNumberOfNodes() do held[n] = {false, false} end
for _, n in ipairs(MA:getNodes('GAUCHE')) do held[n][1] = true end
for _, n in ipairs(MA:getNodes('DROITE')) do held[n][1] = true end
for _, n in ipairs(MA:getNodes('BAS')) do held[n][2] = true end
local function residual(k)
  local Rk = run(L1, {ITER_GLOB_MAXI = k, RESI_GLOB_RELA = 1e-14, ARRET = 'NON'})
  local it = Rk:getAccessParameters().ITER_GLOB
  assert(it[2] == k, string.format('ITER_GLOB_MAXI = %d: %d iterations', k, it[2]))
  local r, largest = Rk:getField('REAC_NODA', 1.0):getValues(), 0.0
  for n = 1, MA:getNumberOfNodes() do
    for c = 1, 2 do
      if not held[n][c] then largest = math.max(largest, math.abs(r[2 * n - 2 + c])) end
    end
  end
  return largest
end
local r = {residual(1), residual(2), residual(3), residual(4)}
print(string.format('GDEF_LOG residuals: %.3e %.3e %.3e %.3e', r[1], r[2], r[3], r[4]))
-- Quadratic: r_k+1 / r_k^2 stays near one constant C (here about 4e-3) while r_k falls
-- by orders of magnitude, with C r_1 small (Newton's region of quadratic convergence).
local C = r[2] / (r[1] * r[1])
assert(C * r[1] < 0.1, string.format('r2 / r1^2 = %.3e: C r1 = %.3e is not small', C, C * r[1]))
for k = 2, 3 do
  local ratio = r[k + 1] / (r[k] * r[k])
  assert(ratio < 10 * C and ratio > C / 10,
         string.format('not quadratic: r%d / r%d^2 = %.3e, r2 / r1^2 = %.3e', k + 1, k, ratio, C))
end
assert(r[4] < 1e-6, string.format('r4 = %.3e', r[4]))
-- 3. C_PLAN (the same loads) and AXIS (the patch as a section r, z; DY = a t on HAUT,
--    DY = 0 on BAS, r free): uniaxial stress, the lateral stretches l^-NU, the axial
--    Cauchy stress E ln(l) / J with J = l^(1 - 2 NU), the others zero.
local function uniaxial(modelisation, axial, loaded)
  local M = AFFE_MODELE{MAILLAGE = MA,
                        AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = modelisation}}
  local held = {{GROUP_MA = 'BAS', DY = 0.0}}
  if axial == 1 then held[2] = {GROUP_MA = 'GAUCHE', DX = 0.0} end
  local pull = {GROUP_MA = loaded}
  pull[axial == 1 and 'DX' or 'DY'] = a
  local fixed = AFFE_CHAR_MECA{MODELE = M, DDL_IMPO = held}
  local pulled = AFFE_CHAR_MECA{MODELE = M, DDL_IMPO = pull}
  local Ru = STAT_NON_LINE{MODELE = M, CHAM_MATER = CM,
                           EXCIT = {{CHARGE = fixed}, {CHARGE = pulled, FONC_MULT = RAMPE}},
                           COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GDEF_LOG'},
                           CONVERGENCE = {RESI_GLOB_RELA = 1e-12, ITER_GLOB_MAXI = 20}, INCREMENT = {LIST_INST = L2}}
  local l = 1 + a / 2
  local lateral, J = l ^ -NU, l ^ (1 - 2 * NU)
  local u = Ru:getField('DEPL', 1.0):getValues()
  for n = 1, MA:getNumberOfNodes() do
    local x, y = xyz[3 * n - 2], xyz[3 * n - 1]
    local ex, ey = (axial == 1 and l or lateral) - 1, (axial == 2 and l or lateral) - 1
    near(u[2 * n - 1], ex * x, 1e-10, string.format('%s: DX of node %d', modelisation, n))
    near(u[2 * n], ey * y, 1e-10, string.format('%s: DY of node %d', modelisation, n))
  end
  local s = E * math.log(l) / J
  local cauchy = {SIXX = axial == 1 and s or 0.0, SIYY = axial == 2 and s or 0.0, SIZZ = 0.0, SIXY = 0.0}
  local sief = Ru:getField('SIEF_ELGA', 1.0)
  local cmp, v = sief:getComponents(), sief:getValues()
  for i = 1, #v do
    local k = cmp[(i - 1) % #cmp + 1]
    near(v[i], cauchy[k], 1e-9 * s, string.format('%s: SIEF_ELGA %s value %d', modelisation, k, i))
  end
end
uniaxial('C_PLAN', 1, 'DROITE')
uniaxial('AXIS', 2, 'HAUT')
print('GDEF_LOG: every check passed')
