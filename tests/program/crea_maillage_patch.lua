-- expect-exit: 0
-- expect-output: CREA_MAILLAGE PATCH: every check passed
-- The cells CREA_MAILLAGE makes are valid finite elements: a linear elastic patch test
-- (MECA_STATIQUE, D_PLAN, E = 200, NU = 0.3) on the distorted patches of [0, 2] x [0, 2]
-- (patch_<type>.mail) after LINE_QUAD (TRIA3 -> TRIA6, QUAD4 -> QUAD8, the boundary SEG2 ->
-- SEG3), MODI_MAILLE QUAD8_9 and DECOUPE_LAC (slave side BAS). The sides carry the tractions
-- of the uniform stress SXX = 3, SYY = -1.25, SXY = 0.8; P1 = (0, 0) is fixed and P2 = (2, 0)
-- has DY = 0, so the exact displacement is linear, u = H x with
-- H = [[EPXX, 2 EPXY], [0, EPYY]] (plane strain Hooke's law), and must be reproduced at
-- every node, the new ones included, to 1e-10 relative.
-- Node counts are checked against Euler's formula: a patch of V vertices and F cells, a disk,
-- has E = V + F - 1 edges, so LINE_QUAD gives V + E nodes; QUAD_LINE gives back V nodes.
local E, NU = 200.0, 0.3
local SXX, SYY, SXY = 3.0, -1.25, 0.8
local EXX = ((1 - NU * NU) * SXX - NU * (1 + NU) * SYY) / E
local EYY = ((1 - NU * NU) * SYY - NU * (1 + NU) * SXX) / E
local EXY = (1 + NU) * SXY / E

local function check(cond, what)
  if not cond then error(what, 2) end
end

local MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}

-- The patch test on mesh M; returns the number of nodes checked.
local function patchTest(M, what)
  local MO = AFFE_MODELE{MAILLAGE = M, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
  local CM = AFFE_MATERIAU{MAILLAGE = M, AFFE = {TOUT = 'OUI', MATER = MAT}}
  local BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_NO = 'P1', DX = 0.0, DY = 0.0}, {GROUP_NO = 'P2', DY = 0.0}}}
  local TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {
    {GROUP_MA = 'DROITE', FX = SXX, FY = SXY}, {GROUP_MA = 'HAUT', FX = SXY, FY = SYY},
    {GROUP_MA = 'GAUCHE', FX = -SXX, FY = -SXY}, {GROUP_MA = 'BAS', FX = -SXY, FY = -SYY}}}
  local R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR}}}
  local u = R:getField('DEPL', 0.0):getValues()
  local x = M:getCoordinates()
  local n = M:getNumberOfNodes()
  check(#u == 2 * n, what .. ': ' .. #u .. ' displacement values for ' .. n .. ' nodes')
  local scale = 2 * (math.abs(EXX) + math.abs(EYY) + math.abs(EXY))
  for i = 1, n do
    local px, py = x[3 * i - 2], x[3 * i - 1]
    local ux, uy = EXX * px + 2 * EXY * py, EYY * py
    check(math.abs(u[2 * i - 1] - ux) <= 1e-10 * scale and math.abs(u[2 * i] - uy) <= 1e-10 * scale,
          string.format('%s: node %d at (%g, %g): u = (%.17g, %.17g), expected (%.17g, %.17g)',
                        what, i, px, py, u[2 * i - 1], u[2 * i], ux, uy))
  end
  return n
end

local function read(name)
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = name}
  local M = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
  DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 20}
  return M
end

-- LINE_QUAD on TRIA3 (V = 9, F = 8, E = 16) and QUAD4 (V = 9, F = 4, E = 12), then back.
for _, case in ipairs({{'patch_tria3.mail', 9, 8}, {'patch_quad4.mail', 9, 4}}) do
  local file, V, F = table.unpack(case)
  local M = read(file)
  local Q = CREA_MAILLAGE{MAILLAGE = M, LINE_QUAD = {TOUT = 'OUI'}}
  local edges = V + F - 1
  check(Q:getNumberOfNodes() == V + edges, file .. ': LINE_QUAD gives ' .. Q:getNumberOfNodes() ..
        ' nodes, expected ' .. V + edges)
  check(Q:getNumberOfCells() == M:getNumberOfCells(), file .. ': LINE_QUAD changed the number of cells')
  check(#Q:getNodes('P1') == 1 and #Q:getNodes('BAS') == 5, file .. ': groups after LINE_QUAD')
  patchTest(Q, file .. ' LINE_QUAD')
  local L = CREA_MAILLAGE{MAILLAGE = Q, QUAD_LINE = {TOUT = 'OUI'}}
  check(L:getNumberOfNodes() == V, file .. ': QUAD_LINE gives ' .. L:getNumberOfNodes() .. ' nodes')
  patchTest(L, file .. ' QUAD_LINE')
end

-- QUAD8 -> QUAD9: one centre node per cell.
local M8 = read('patch_quad8.mail')
local M9 = CREA_MAILLAGE{MAILLAGE = M8, MODI_MAILLE = {TOUT = 'OUI', OPTION = 'QUAD8_9'}}
check(M9:getNumberOfNodes() == M8:getNumberOfNodes() + 4, 'QUAD8_9: one new node per QUAD8')
patchTest(M9, 'QUAD8_9')

-- DECOUPE_LAC with BAS as the slave side: TRIA3 (2 slave segments, 1 node each) and QUAD4
-- (2 slave segments, 4 nodes and 3 + 3 cells more each).
local T = read('patch_tria3.mail')
local TL = CREA_MAILLAGE{MAILLAGE = T, DECOUPE_LAC = {GROUP_MA_ESCL = 'BAS'}}
check(TL:getNumberOfNodes() == 9 + 2 and #TL:getCells('BAS') == 4, 'DECOUPE_LAC TRIA3: counts')
patchTest(TL, 'DECOUPE_LAC TRIA3')
local Q4 = read('patch_quad4.mail')
local QL = CREA_MAILLAGE{MAILLAGE = Q4, DECOUPE_LAC = {GROUP_MA_ESCL = 'BAS'}}
check(QL:getNumberOfNodes() == 9 + 8 and #QL:getCells('BAS') == 6 and #QL:getCells('SURFACE') == 2 * 4 + 2,
      'DECOUPE_LAC QUAD4: counts')
patchTest(QL, 'DECOUPE_LAC QUAD4')
print('CREA_MAILLAGE PATCH: every check passed')
