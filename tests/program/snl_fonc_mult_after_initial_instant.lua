-- expect-exit: 2
-- expect-output: FONC_MULT after the initial instant: every check passed.<F> <R:getField> [^ ]+: NOM_CHAM='REAC_NODA' is not stored in the result at INST=0 \(fields: DEPL, FORC_NODA, SIEF_ELGA\)
-- A FONC_MULT that is not defined at the initial instant (tabulated from INST = 0.5,
-- PROL_GAUCHE='EXCLU'), as code_aster's SSNP152 A: the initial state is given, so
-- STAT_NON_LINE never needs the loads there; the first step goes from the given
-- state to the loads at its end. The unit square (one QUAD4), PETIT, D_PLAN,
-- E = 200, NU = 0.3, DX = 0 on GAUCHE, DY = 0 at P1 = (0, 0), and on DROITE either
--   * a force (F, 0) at each of P2 = (1, 0) and P3 = (1, 1) times f(t): the uniform
--     stress sigma_xx = 2 F f(t), u_x = (1 - NU^2) / E sigma_xx x,
--     u_y = -NU (1 + NU) / E sigma_xx y;
--   * or DX = D times f(t) imposed: the uniform strain eps_xx = D f(t), so
--     sigma_xx = E / (1 - NU^2) eps_xx, u_x = eps_xx x, u_y = -NU / (1 - NU) eps_xx y,
--     and the reactions on DROITE sum to sigma_xx;
-- with f(t) = t on [0.5, 1] and instants 0, 0.5, 1. NUME_ORDRE 0 holds the given
-- state (zero displacements) without REAC_NODA (the loads are not defined there);
-- with a FONC_MULT defined at 0 it has REAC_NODA (zero). The study ends asking for
-- the absent field: the fatal error that names the fields stored at INST 0.
local E, NU, F, D = 200.0, 0.3, 1.5, 0.01
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
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
LATE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.5, 0.5, 1.0, 1.0}, PROL_GAUCHE = 'EXCLU', PROL_DROITE = 'EXCLU'}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
FORCE = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = F}}
PULL = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'DROITE', DX = D}}
xyz = MA:getCoordinates()
local right = {}
for _, n in ipairs(MA:getNodes('DROITE')) do right[n] = true end

local late
for _, case in ipairs({{'FORCE_NODALE', FORCE, function(t) return 2 * F * t end},
                       {'DDL_IMPO', PULL, function(t) return E / (1 - NU * NU) * D * t end}}) do
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = case[2], FONC_MULT = LATE}},
                          COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L}}
  local u0 = R:getField('DEPL', 0.0):getValues()
  for i = 1, #u0 do near(u0[i], 0.0, 0.0, case[1] .. ': DEPL at INST 0, unknown ' .. i) end
  late = R
  for _, t in ipairs({0.5, 1.0}) do
    local what = string.format('%s at INST %g', case[1], t)
    local s = case[3](t)
    local u = R:getField('DEPL', t):getValues()
    local r = R:getField('REAC_NODA', t):getValues()
    local pulled = 0.0
    for n = 1, MA:getNumberOfNodes() do
      near(u[2 * n - 1], (1 - NU * NU) / E * s * xyz[3 * n - 2], 1e-14, what .. ': DX of node ' .. n)
      near(u[2 * n], -NU * (1 + NU) / E * s * xyz[3 * n - 1], 1e-14, what .. ': DY of node ' .. n)
      if right[n] then pulled = pulled + r[2 * n - 1] end
    end
    -- The reactions on DROITE balance the imposed stretch; with the forces, DROITE is free.
    near(pulled, case[1] == 'DDL_IMPO' and s or 0.0, 1e-12, what .. ': sum of the reactions on DROITE')
  end
end

-- A FONC_MULT defined at the initial instant: REAC_NODA is stored there (zero: no load at 0).
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = FORCE, FONC_MULT = RAMPE}},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L}}
local r0 = R:getField('REAC_NODA', 0.0):getValues()
for i = 1, #r0 do near(r0[i], 0.0, 0.0, 'RAMPE: REAC_NODA at INST 0, unknown ' .. i) end
print('FONC_MULT after the initial instant: every check passed')
late:getField('REAC_NODA', 0.0)
