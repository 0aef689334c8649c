-- expect-exit: 0
-- expect-output: SANS_\*: every check passed
-- DDL_IMPO on every node but those SANS_NOEUD, SANS_GROUP_NO, SANS_MAILLE, SANS_GROUP_MA
-- leave out, against the stiffness of the free node by hand. The rectangle [0,4] x [0,1]
-- of four unit-square QUAD4 (rectangle_4x1.mail), D_PLAN, E = 1000, NU = 0.3. For a unit
-- square of bilinear shape functions (integrated exactly by 2 x 2 Gauss points) the block of
-- a corner node is K_xx = K_yy = (D11 + D33) / 3, K_xy = +-(D12 + D33) / 4 (+ at the corners
-- (0,0) and (1,1) of the square, - at the two others), with D11 = E (1 - NU) / ((1 + NU)(1 - 2 NU)),
-- D12 = E NU / ((1 + NU)(1 - 2 NU)), D33 = E / (2 (1 + NU)).
--  1. Only N8 = (2, 1) free, top corner of M2 and M3: K_xx = 2 (D11 + D33) / 3, K_xy = 0, so
--     FX = F gives u_x = 3 F / (2 (D11 + D33)), u_y = 0.
--  2. Only N5 = (4, 0) free (SANS_MAILLE M6 frees N5 and N10, and N10 is held again by
--     NOEUD), bottom-right corner of M4: [a b; b a] u = [F 0] with a = (D11 + D33) / 3,
--     b = -(D12 + D33) / 4.
local E, NU, F = 1000.0, 0.3, 10.0
local D11 = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU))
local D12 = E * NU / ((1 + NU) * (1 - 2 * NU))
local D33 = E / (2 * (1 + NU))
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'rectangle_4x1.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MA = DEFI_GROUP{reuse = MA, MAILLAGE = MA, CREA_GROUP_NO = {NOM = 'P8', NOEUD = 'N8'}}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}

local function solve(fixed, node)
  local bc = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = fixed}
  local load = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {NOEUD = node, FX = F}}
  local res = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = bc}, {CHARGE = load}}}
  return res:getField('DEPL', 0.0):getValues()
end

-- Only the node `free` (1-based index) moves, by (ux, uy).
local function check(u, free, ux, uy, what)
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], n == free and ux or 0.0, 1e-12 * math.abs(ux), what .. ': DX of node ' .. n)
    near(u[2 * n], n == free and uy or 0.0, 1e-12 * math.abs(ux), what .. ': DY of node ' .. n)
  end
end

local ux8 = 3 * F / (2 * (D11 + D33))
check(solve({TOUT = 'OUI', SANS_NOEUD = 'N8', DX = 0.0, DY = 0.0}, 'N8'), 8, ux8, 0.0, 'SANS_NOEUD')
check(solve({TOUT = 'OUI', SANS_GROUP_NO = 'P8', DX = 0.0, DY = 0.0}, 'N8'), 8, ux8, 0.0, 'SANS_GROUP_NO')

local a, b = (D11 + D33) / 3, -(D12 + D33) / 4
local ux5, uy5 = F * a / (a * a - b * b), -F * b / (a * a - b * b)
check(solve({{MAILLE = {'M1', 'M2', 'M3', 'M4'}, SANS_MAILLE = 'M6', DX = 0.0, DY = 0.0},
             {NOEUD = 'N10', DX = 0.0, DY = 0.0}}, 'N5'), 5, ux5, uy5, 'SANS_MAILLE')
check(solve({{GROUP_MA = 'SURFACE', SANS_GROUP_MA = 'DROITE', DX = 0.0, DY = 0.0},
             {NOEUD = 'N10', DX = 0.0, DY = 0.0}}, 'N5'), 5, ux5, uy5, 'SANS_GROUP_MA')
-- The same through AFFE_CHAR_CINE (elimination), MAILLE selecting the nodes of cells.
BCC = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {{MAILLE = {'M1', 'M2', 'M3'}, DX = 0.0, DY = 0.0},
                                                {NOEUD = 'N10', DX = 0.0, DY = 0.0}}}
FO5 = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {NOEUD = 'N5', FX = F}}
RC = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BCC}, {CHARGE = FO5}}}
check(RC:getField('DEPL', 0.0):getValues(), 5, ux5, uy5, 'AFFE_CHAR_CINE MAILLE')
print('SANS_*: every check passed')
