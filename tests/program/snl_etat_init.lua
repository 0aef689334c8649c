-- expect-exit: 0
-- expect-output: ETAT_INIT: every check passed
-- STAT_NON_LINE's ETAT_INIT and reuse=. The unit square (one QUAD4), D_PLAN,
-- GROT_GDEP, E = 200, NU = 0.3, DX = 0 on GAUCHE, DY = 0 on BAS, DX = a t on DROITE
-- (a = 0.4, ten steps to t = 1): the exact homogeneous stretch x = l1 X, y = l2 Y,
-- l1 = 1 + a t, E11 = (l1^2 - 1) / 2, l2 = sqrt(1 - 2 NU / (1 - NU) E11).
-- A run to t = 0.5 (NUME_INST_FIN = 5) continued from its last instant (ETAT_INIT/EVOL_NOLI; the
-- initial instant is ETAT_INIT's by default) gives the same answer at t = 1 as one
-- run (both exact to the tolerance); so do a continuation with reuse= (the result
-- then holds every instant 0 .. 1), a restart from an earlier instant of a result
-- (NUME_ORDRE = 3: the later instants are computed again), and a start from a
-- displacement field (ETAT_INIT/DEPL, from NUME_INST_INIT = 5).
local E, NU, a = 200.0, 0.3, 0.4
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, x, y), 2)
  end
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
local function keywords(extra, increment)
  local k = {MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = ST, FONC_MULT = RAMPE}},
             COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
             CONVERGENCE = {RESI_GLOB_RELA = 1e-10}, INCREMENT = {LIST_INST = L}}
  for key, v in pairs(extra or {}) do k[key] = v end
  for key, v in pairs(increment or {}) do k.INCREMENT[key] = v end
  return k
end
local function instants(R)
  local s = {}
  for _, t in ipairs(R:getAccessParameters().INST) do s[#s + 1] = string.format('%g', t) end
  return table.concat(s, ' ')
end
local ONE = STAT_NON_LINE(keywords())
local reference = ONE:getField('DEPL', 1.0):getValues()
local function checkFinal(R, what)
  local l1 = 1 + a
  local l2 = math.sqrt(1 - 2 * NU / (1 - NU) * (l1 * l1 - 1) / 2)
  local u = R:getField('DEPL', 1.0):getValues()
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], (l1 - 1) * xyz[3 * n - 2], 1e-9, what .. ': DX of node ' .. n)
    near(u[2 * n], (l2 - 1) * xyz[3 * n - 1], 1e-9, what .. ': DY of node ' .. n)
    near(u[2 * n], reference[2 * n], 1e-9, what .. ': DY of node ' .. n .. ' against one run')
  end
end
checkFinal(ONE, 'one run')

-- Continued from the last instant of a run to 0.5.
HALF = STAT_NON_LINE(keywords({}, {NUME_INST_FIN = 5}))
assert(instants(HALF) == '0 0.1 0.2 0.3 0.4 0.5', 'first half: ' .. instants(HALF))
REST = STAT_NON_LINE(keywords({ETAT_INIT = {EVOL_NOLI = HALF}}))
assert(instants(REST) == '0.5 0.6 0.7 0.8 0.9 1', 'second half: ' .. instants(REST))
checkFinal(REST, 'ETAT_INIT/EVOL_NOLI')

-- reuse=: the same result continued.
HALF = STAT_NON_LINE(keywords({reuse = HALF, ETAT_INIT = {EVOL_NOLI = HALF}}))
assert(instants(HALF) == '0 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1', 'reuse: ' .. instants(HALF))
checkFinal(HALF, 'reuse=')

-- A restart from NUME_ORDRE = 3 (t = 0.3) of a complete result: 0.4 .. 1 computed again.
ONE = STAT_NON_LINE(keywords({reuse = ONE, ETAT_INIT = {EVOL_NOLI = ONE, NUME_ORDRE = 3}}))
assert(instants(ONE) == '0 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9 1', 'restart: ' .. instants(ONE))
local numbers = ONE:getAccessParameters().NUME_ORDRE
for i, n in ipairs(numbers) do assert(n == i - 1, 'restart: NUME_ORDRE ' .. n .. ' at position ' .. i) end
checkFinal(ONE, 'ETAT_INIT/NUME_ORDRE')

-- From a displacement field.
local U05 = REST:getField('DEPL', 0.5)
FROMDEPL = STAT_NON_LINE(keywords({ETAT_INIT = {DEPL = U05}}, {NUME_INST_INIT = 5}))
assert(instants(FROMDEPL) == '0.5 0.6 0.7 0.8 0.9 1', 'ETAT_INIT/DEPL: ' .. instants(FROMDEPL))
checkFinal(FROMDEPL, 'ETAT_INIT/DEPL')
print('ETAT_INIT: every check passed')
