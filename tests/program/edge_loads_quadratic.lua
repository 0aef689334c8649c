-- expect-exit: 0
-- expect-output: EDGE_LOADS: every check passed
-- PRES_REP and FORCE_CONTOUR on SEG3 edges of QUAD9, QUAD8 and TRIA6 cells (the strip
-- [0, 3] x [0, 1], quadratic_strip.mail), D_PLAN, E = 1000, NU = 0.3: PRES_REP = p on BAS
-- and HAUT, FORCE_CONTOUR FX = p on GAUCHE and FX = -p on DROITE (the same pressure
-- written as a traction), DX = DY = 0 at P1 and DY = 0 at P3 (by NOEUD): the uniform
-- state sigma_xx = sigma_yy = -p, sigma_zz = -2 NU p, u = eps (x, y) with
-- eps = -(1 + NU) (1 - 2 NU) p / E; reactions zero. MECA_STATIQUE and STAT_NON_LINE.
local E, NU, p = 1000.0, 0.3, 2.5
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'quadratic_strip.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{NOEUD = 'N1', DX = 0.0, DY = 0.0}, {GROUP_NO = 'P3', DY = 0.0}},
                    PRES_REP = {GROUP_MA = {'BAS', 'HAUT'}, PRES = p},
                    FORCE_CONTOUR = {{GROUP_MA = 'GAUCHE', FX = p}, {GROUP_MA = 'DROITE', FX = -p}}}
RS = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INST = 1.0}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
RN = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, COMPORTEMENT = {RELATION = 'ELAS'},
                   INCREMENT = {LIST_INST = L1}}
local xyz = MA:getCoordinates()
local eps = -(1 + NU) * (1 - 2 * NU) * p / E
for _, case in ipairs({{RS, 'MECA_STATIQUE'}, {RN, 'STAT_NON_LINE'}}) do
  local res, what = case[1], case[2]
  local u = res:getField('DEPL', 1.0):getValues()
  local r = res:getField('REAC_NODA', 1.0):getValues()
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], eps * xyz[3 * n - 2], 1e-13, what .. ': DX of node ' .. n)
    near(u[2 * n], eps * xyz[3 * n - 1], 1e-13, what .. ': DY of node ' .. n)
    near(r[2 * n - 1], 0.0, 1e-10 * p, what .. ': DX reaction of node ' .. n)
    near(r[2 * n], 0.0, 1e-10 * p, what .. ': DY reaction of node ' .. n)
  end
  local sief = res:getField('SIEF_ELGA', 1.0)
  local cmp, v = sief:getComponents(), sief:getValues()
  local exact = {SIXX = -p, SIYY = -p, SIZZ = -2 * NU * p, SIXY = 0.0}
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], exact[c], 1e-10 * p, what .. ': SIEF_ELGA ' .. c .. ' value ' .. i)
  end
end
print('EDGE_LOADS: every check passed')
