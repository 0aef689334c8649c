-- expect-exit: 0
-- expect-output: MACR_ADAP_MAIL GROUP_NO: every check passed
-- A DDL_IMPO by GROUP_NO on a refined mesh holds the new nodes of that boundary.
-- The bar [0,2] x [0,1] (two QUAD4), DX = 0 on GROUP_NO GAUCHE (exactly the
-- nodes of GROUP_MA GAUCHE, the left edge), DY = 0 at P1 = (0, 0), traction
-- S along X on DROITE, PETIT, D_PLAN, refined twice. GAUCHE follows its
-- cells: 5 nodes on x = 0 after two refinements; P1 stays one node. The exact
-- solution is the uniform stress sigma_xx = S, which bilinear elements
-- reproduce to rounding:
--   u_x = (1 - NU^2) / E S x,   u_y = -NU (1 + NU) / E S y.
-- With the new left nodes free (the group keeping its old 2 nodes), u_x would
-- not vanish at (0, 0.5) and the field would not be uniform.
local E, NU, S = 200.0, 0.3, 3.0
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, x, y), 2)
  end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'rectangle_groups.mail'}
MA0 = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA0, MAILLAGE_NP1 = CO('MA1')}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA1, MAILLAGE_NP1 = CO('MA')}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_NO = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
TRACTION = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = S}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TRACTION}},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L}}

local xyz = MA:getCoordinates()
local u = R:getField('DEPL', 1.0):getValues()
local middle = false
for n = 1, MA:getNumberOfNodes() do
  local x, y = xyz[3 * n - 2], xyz[3 * n - 1]
  near(u[2 * n - 1], (1 - NU * NU) / E * S * x, 1e-14, string.format('DX at (%g, %g)', x, y))
  near(u[2 * n], -NU * (1 + NU) / E * S * y, 1e-14, string.format('DY at (%g, %g)', x, y))
  if x == 0.0 and y == 0.5 then middle = true end
end
assert(middle, 'no node at (0, 0.5)')
local left = MA:getNodes('GAUCHE')
assert(#left == 5, 'GAUCHE has ' .. #left .. ' nodes, expected 5')
for _, n in ipairs(left) do near(xyz[3 * n - 2], 0.0, 0.0, 'X of GAUCHE node ' .. n) end
assert(#MA:getNodes('P1') == 1)
print('MACR_ADAP_MAIL GROUP_NO: every check passed')
