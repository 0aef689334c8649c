-- expect-exit: 0
-- expect-output: FORCE_NODALE: every check passed
-- FORCE_NODALE at command level. The unit square (one QUAD4), PETIT, D_PLAN,
-- E = 200, NU = 0.3, DX = 0 on GAUCHE, DY = 0 at P1 = (0, 0), and a force (F, 0)
-- at each of P2 = (1, 0) and P3 = (1, 1) (each node of GROUP_NO gets the full
-- force), scaled by FONC_MULT f(t) = t at t = 0.5 and 1. For a QUAD4 these are the
-- consistent nodal loads of a traction 2F per unit length on DROITE, so the exact
-- solution is the uniform stress sigma_xx = 2 F t (sigma_yy = sigma_xy = 0):
--   u_x = (1 - NU^2) / E 2 F t x,   u_y = -NU (1 + NU) / E 2 F t y.
-- The total force matches: the reactions on GAUCHE sum to -2 F t, FORC_NODA is F t
-- at P2 and P3. The same with AFFE_CHAR_MECA_F and FX = F X (a formula of X, Y):
-- F at both loaded nodes, X = 1.
local E, NU, F = 200.0, 0.3, 1.5
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
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
FXF = FORMULE{VALE = string.format('%.17g*X', F), NOM_PARA = {'X', 'Y'}}
xyz = MA:getCoordinates()
local loaded = {}
for _, g in ipairs({'P2', 'P3'}) do loaded[MA:getNodes(g)[1]] = true end
local left = {}
for _, n in ipairs(MA:getNodes('GAUCHE')) do left[n] = true end

for _, load in ipairs({
    {'AFFE_CHAR_MECA', AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = F}}},
    {'AFFE_CHAR_MECA_F', AFFE_CHAR_MECA_F{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = FXF}}}}) do
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = load[2], FONC_MULT = RAMPE}},
                          COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L}}
  for _, t in ipairs({0.5, 1.0}) do
    local what = string.format('%s at INST %g', load[1], t)
    local s = 2 * F * t
    local u = R:getField('DEPL', t):getValues()
    local f = R:getField('FORC_NODA', t):getValues()
    local r = R:getField('REAC_NODA', t):getValues()
    local reactions = 0.0
    for n = 1, MA:getNumberOfNodes() do
      near(u[2 * n - 1], (1 - NU * NU) / E * s * xyz[3 * n - 2], 1e-14, what .. ': DX of node ' .. n)
      near(u[2 * n], -NU * (1 + NU) / E * s * xyz[3 * n - 1], 1e-14, what .. ': DY of node ' .. n)
      if loaded[n] then near(f[2 * n - 1], F * t, 1e-12, what .. ': FORC_NODA DX of node ' .. n) end
      if left[n] then reactions = reactions + r[2 * n - 1] end
    end
    near(reactions, -2 * F * t, 1e-12, what .. ': sum of the reactions on GAUCHE')
  end
end
print('FORCE_NODALE: every check passed')
