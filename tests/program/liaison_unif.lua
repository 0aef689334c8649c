-- expect-exit: 0
-- expect-output: LIAISON_UNIF: every check passed
-- LIAISON_UNIF on the top edge of a block under one nodal force. The block [0, 2] x [0, 1]
-- (4 x 2 QUAD4, interior nodes moved), D_PLAN, E = 1000, NU = 0.3: DY = 0 on BAS, DX = 0
-- at N1 (by NOEUD), LIAISON_UNIF DY on the nodes of HAUT, FY = F at the top node N13 alone
-- (FORCE_NODALE by NOEUD). The top moves as one, so the exact solution is the uniform
-- uniaxial stress sigma_yy = F / L (L = 2, the block's width), sigma_xx = sigma_xy = 0,
-- sigma_zz = NU sigma_yy, with u_x = -NU (1 + NU) sigma_yy / E x, u_y = (1 - NU^2) sigma_yy / E y:
-- linear, so exact on the mesh. The relations pass the force on to the other top nodes:
-- their reactions (REAC_NODA, the residual there) sum to zero over the top, and those on
-- BAS to -F. Solved by MECA_STATIQUE and by STAT_NON_LINE (Newton, the same elimination).
local E, NU, F, L = 1000.0, 0.3, 10.0, 2.0
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'liaison_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {NOEUD = 'N1', DX = 0.0}},
                    LIAISON_UNIF = {GROUP_MA = 'HAUT', DDL = 'DY'}}
FO = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {NOEUD = 'N13', FY = F}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
RS = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = FO}}, INST = 1.0}
RN = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = FO}},
                   COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L1}}

local xyz = MA:getCoordinates()
local function set(group)
  local s = {}
  for _, n in ipairs(MA:getNodes(group)) do s[n] = true end
  return s
end
local bottom, top = set('BAS'), set('HAUT')
local syy = F / L
local ex, ey = -NU * (1 + NU) * syy / E, (1 - NU * NU) * syy / E

local function check(res, what)
  local u = res:getField('DEPL', 1.0):getValues()
  local r = res:getField('REAC_NODA', 1.0):getValues()
  local sumBottom, sumTop = 0.0, 0.0
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], ex * xyz[3 * n - 2], 1e-12, what .. ': DX of node ' .. n)
    near(u[2 * n], ey * xyz[3 * n - 1], 1e-12, what .. ': DY of node ' .. n)
    if bottom[n] then sumBottom = sumBottom + r[2 * n] end
    if top[n] then sumTop = sumTop + r[2 * n] end
  end
  near(sumBottom, -F, 1e-10 * F, what .. ': sum of the DY reactions on BAS')
  near(sumTop, 0.0, 1e-10 * F, what .. ': sum of the DY reactions on HAUT (what the relations pass on)')
  local sief = res:getField('SIEF_ELGA', 1.0)
  local cmp, v = sief:getComponents(), sief:getValues()
  local exact = {SIXX = 0.0, SIYY = syy, SIZZ = NU * syy, SIXY = 0.0}
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], exact[c], 1e-10 * syy, what .. ': SIEF_ELGA ' .. c .. ' value ' .. i)
  end
end
check(RS, 'MECA_STATIQUE')
check(RN, 'STAT_NON_LINE')
print('LIAISON_UNIF: every check passed')
