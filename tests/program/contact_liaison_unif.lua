-- expect-exit: 0
-- expect-output: CONTACT_LIAISON_UNIF: every check passed
-- Linear relations with contact terms in the Newton matrix: contact_two_blocks.lua's two
-- blocks (QUAD4 and QUAD8, frictionless contact between BLOC_HAUT's ESCLAVE and BLOC_BAS's
-- MAITRE, DISCRETE and CONTINUE), but the top HAUT (width 1) moves as one (LIAISON_UNIF DY)
-- and the load is one nodal force -P at its right corner (N18, N40), not a traction. The
-- relations spread the force: the closed form is contact_two_blocks.lua's, uniform
-- SIYY = -P, SIXX = SIXY = 0, the top sunk by (1 - NU^2) P / E times the height 0.6, the
-- contact pressure RN = -P at every slave node; the DY reactions on HAUT (what the
-- relations pass on) sum to zero.
E, NU, P = 2.1E11, 0.3, 1.0E7
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
for k, case in ipairs({{'quad4', 'N18', 18, 3}, {'quad8', 'N40', 40, 5}}) do
  local cell, corner, cornerIndex, slaves = case[1], case[2], case[3], case[4]
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19 + k, FICHIER = 'contact_two_blocks_' .. cell .. '.mail'}
  local MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 19 + k}
  MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'ESCLAVE'}}}
  local xyz = MA:getCoordinates()
  near(xyz[3 * cornerIndex - 2], 1.0, 0.0, cell .. ': X of ' .. corner)
  near(xyz[3 * cornerIndex - 1], 0.6, 0.0, cell .. ': Y of ' .. corner)
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  local LOAD = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}},
                              LIAISON_UNIF = {GROUP_MA = 'HAUT', DDL = 'DY'},
                              FORCE_NODALE = {NOEUD = corner, FY = -P}}
  local top = {}
  for _, n in ipairs(MA:getNodes('HAUT')) do top[n] = true end
  for _, formulation in ipairs({'DISCRETE', 'CONTINUE'}) do
    local what = cell .. ' ' .. formulation
    local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = LOAD}},
      CONTACT = DEFI_CONTACT{MODELE = MO, FORMULATION = formulation,
                             ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'ESCLAVE'}},
      COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
    local sief = R:getField('SIEF_ELGA', 1.0)
    local cmp, v = sief:getComponents(), sief:getValues()
    local exact = {SIXX = 0.0, SIYY = -P, SIZZ = -NU * P, SIXY = 0.0}
    for i = 1, #v do
      local c = cmp[(i - 1) % #cmp + 1]
      near(v[i], exact[c], 1e-9 * P, what .. ': SIEF_ELGA ' .. c .. ' value ' .. i)
    end
    -- Node after node, getComponents() each (CONTINUE's DEPL has LAGS_C too).
    local depl, reac = R:getField('DEPL', 1.0), R:getField('REAC_NODA', 1.0)
    local u, nu = depl:getValues(), #depl:getComponents()
    local r, nr = reac:getValues(), #reac:getComponents()
    local sumTop = 0.0
    for n in pairs(top) do
      near(u[nu * (n - 1) + 2], -(1 - NU * NU) * P / E * 0.6, 1e-9 * P / E, what .. ': DY of top node ' .. n)
      sumTop = sumTop + r[nr * (n - 1) + 2]
    end
    near(sumTop, 0.0, 1e-9 * P, what .. ': sum of the DY reactions on HAUT')
    local rn = R:getField('CONT_NOEU', 1.0)
    local rcmp, rv = rn:getComponents(), rn:getValues()
    local sum = 0.0
    for i = 1, #rv do
      if rcmp[(i - 1) % #rcmp + 1] == 'RN' then sum = sum + rv[i] end
    end
    near(sum, -P * slaves, 1e-9 * P, what .. ': sum of RN')
  end
end
print('CONTACT_LIAISON_UNIF: every check passed')
