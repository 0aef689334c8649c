-- expect-exit: 0
-- expect-output: LIAISON_SOLIDE: every check passed
-- LIAISON_SOLIDE (2D, linearized rigid motion u(M) = u(A) + theta k x AM).
-- 1. Every node of the distorted QUAD8/TRIA6 patch (patch_quad8_tria6.mail) in one solid,
--    its motion set by DX, DY at P1 = (0, 0) and DY at P2 = (2, 0), a nodal force at P3:
--    u = (a - theta y, b + theta x) exactly, zero stress (to 1e-10 of E theta), and the
--    reactions sum to minus the force.
-- 2. Two unit squares that share no node (liaison_two_blocks.mail), their four interface
--    nodes (two coincident pairs, all on x = 1: the aligned and coincident cases) in one
--    solid, NU = 0, DX = 0 on the left edge, DY = 0 at N1, a traction S on the right edge:
--    the uniform uniaxial state u_x = S x / E, u_y = 0 moves the interface rigidly, so it is
--    the exact solution.
-- 3. The same squares glued by a LIAISON_SOLIDE on each coincident pair (a point: equal
--    displacements) and one on a single node (nothing), NU = 0.3: the uniform state of the
--    whole rectangle, u_x = (1 - NU^2) S / E x, u_y = -NU (1 + NU) S / E y (D_PLAN).
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
local function checkStress(res, exact, tol, what)
  local sief = res:getField('SIEF_ELGA', 1.0)
  local cmp, v = sief:getComponents(), sief:getValues()
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], exact[c], tol, what .. ': SIEF_ELGA ' .. c .. ' value ' .. i)
  end
end

-- 1. The patch.
local E, a, b, theta, FX, FY = 200.0, 1e-3, -2e-3, 5e-4, 3.0, -4.0
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_quad8_tria6.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
CH = AFFE_CHAR_MECA{MODELE = MO, LIAISON_SOLIDE = {GROUP_MA = 'SURFACE'},
                    DDL_IMPO = {{GROUP_NO = 'P1', DX = a, DY = b}, {GROUP_NO = 'P2', DY = b + 2 * theta}},
                    FORCE_NODALE = {GROUP_NO = 'P3', FX = FX, FY = FY}}
R1 = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INST = 1.0}
local xyz = MA:getCoordinates()
local u = R1:getField('DEPL', 1.0):getValues()
local r = R1:getField('REAC_NODA', 1.0):getValues()
local rx, ry = 0.0, 0.0
for n = 1, MA:getNumberOfNodes() do
  local x, y = xyz[3 * n - 2], xyz[3 * n - 1]
  near(u[2 * n - 1], a - theta * y, 1e-15, 'patch: DX of node ' .. n)
  near(u[2 * n], b + theta * x, 1e-15, 'patch: DY of node ' .. n)
  rx, ry = rx + r[2 * n - 1], ry + r[2 * n]
end
near(rx, -FX, 1e-10 * FX, 'patch: sum of the DX reactions')
near(ry, -FY, 1e-10 * FX, 'patch: sum of the DY reactions')
checkStress(R1, {SIXX = 0.0, SIYY = 0.0, SIZZ = 0.0, SIXY = 0.0}, 1e-10 * E * theta, 'patch')

-- 2. and 3. The two squares.
local S = 5.0
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'liaison_two_blocks.mail'}
MB = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MOB = AFFE_MODELE{MAILLAGE = MB, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
BC = AFFE_CHAR_MECA{MODELE = MOB, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}},
                    FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = S}}
local xyzB = MB:getCoordinates()
local function checkUniform(res, nu, what)
  local ex, ey = (1 - nu * nu) * S / E, -nu * (1 + nu) * S / E
  local v = res:getField('DEPL', 1.0):getValues()
  for n = 1, MB:getNumberOfNodes() do
    near(v[2 * n - 1], ex * xyzB[3 * n - 2], 1e-12, what .. ': DX of node ' .. n)
    near(v[2 * n], ey * xyzB[3 * n - 1], 1e-12, what .. ': DY of node ' .. n)
  end
  checkStress(res, {SIXX = S, SIYY = 0.0, SIZZ = nu * S, SIXY = 0.0}, 1e-10 * S, what)
end

M0 = DEFI_MATERIAU{ELAS = {E = E, NU = 0.0}}
CM0 = AFFE_MATERIAU{MAILLAGE = MB, AFFE = {TOUT = 'OUI', MATER = M0}}
RIGID = AFFE_CHAR_MECA{MODELE = MOB, LIAISON_SOLIDE = {GROUP_NO = 'INTERFACE'}}
R2 = MECA_STATIQUE{MODELE = MOB, CHAM_MATER = CM0, EXCIT = {{CHARGE = BC}, {CHARGE = RIGID}}, INST = 1.0}
checkUniform(R2, 0.0, 'rigid interface')

M3 = DEFI_MATERIAU{ELAS = {E = E, NU = 0.3}}
CM3 = AFFE_MATERIAU{MAILLAGE = MB, AFFE = {TOUT = 'OUI', MATER = M3}}
GLUE = AFFE_CHAR_MECA{MODELE = MOB, LIAISON_SOLIDE = {{NOEUD = {'N2', 'N5'}}, {NOEUD = {'N3', 'N8'}}, {NOEUD = 'N6'}}}
R3 = MECA_STATIQUE{MODELE = MOB, CHAM_MATER = CM3, EXCIT = {{CHARGE = BC}, {CHARGE = GLUE}}, INST = 1.0}
checkUniform(R3, 0.3, 'coincident pairs')
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R4 = STAT_NON_LINE{MODELE = MOB, CHAM_MATER = CM3, EXCIT = {{CHARGE = BC}, {CHARGE = GLUE}},
                   COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L1}}
checkUniform(R4, 0.3, 'coincident pairs, STAT_NON_LINE')
print('LIAISON_SOLIDE: every check passed')
