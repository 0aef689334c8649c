-- expect-exit: 0
-- expect-output: MECA_STATIQUE: 3 instant\(s\), 1 factorization\(s\).*AFFE_CHAR_CINE_F: every check passed
-- AFFE_CHAR_CINE_F: displacements that are functions of INST and space, eliminated, over
-- several instants. The block [0, 2] x [0, 1] (liaison_block.mail), D_PLAN, E = 1000,
-- NU = 0.3: DX = 0 on GAUCHE and DY = 0 at N1 (AFFE_CHAR_CINE, by GROUP_MA and NOEUD); on
-- DROITE (X = 2) DX = 2 A t^2 (DEFI_FONCTION of INST, exact at the instants) and
-- DY = -NU / (1 - NU) A t^2 Y (FORMULE of Y and INST). The exact solution is the uniform
-- uniaxial state eps_xx = A t^2: u_x = A t^2 X, u_y = -NU / (1 - NU) A t^2 Y,
-- sigma_xx = E A t^2 / (1 - NU^2). Instants 0.5, 1, 2; MECA_STATIQUE factorizes once.
local E, NU, A = 1000.0, 0.3, 1e-3
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'liaison_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
FIXE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {NOEUD = 'N1', DY = 0.0}}}
DXT = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 0.5, 2 * A * 0.25, 1.0, 2 * A, 2.0, 8 * A}}
DYT = FORMULE{VALE = '-NU / (1 - NU) * A * INST * INST * Y', NU = NU, A = A, NOM_PARA = {'Y', 'INST'}}
TIRE = AFFE_CHAR_CINE_F{MODELE = MO, MECA_IMPO = {GROUP_MA = 'DROITE', DX = DXT, DY = DYT}}
L = DEFI_LIST_REEL{VALE = {0.5, 1.0, 2.0}}
RS = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = FIXE}, {CHARGE = TIRE}}, LIST_INST = L}
LN = DEFI_LIST_REEL{VALE = {0.0, 0.5, 1.0, 2.0}}
RN = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = FIXE}, {CHARGE = TIRE}},
                   COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = LN}}

local xyz = MA:getCoordinates()
local function check(res, t, what)
  local exx = A * t * t
  local u = res:getField('DEPL', t):getValues()
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], exx * xyz[3 * n - 2], 1e-13, what .. ': DX of node ' .. n)
    near(u[2 * n], -NU / (1 - NU) * exx * xyz[3 * n - 1], 1e-13, what .. ': DY of node ' .. n)
  end
  local sxx = E * exx / (1 - NU * NU)
  local sief = res:getField('SIEF_ELGA', t)
  local cmp, v = sief:getComponents(), sief:getValues()
  local exact = {SIXX = sxx, SIYY = 0.0, SIZZ = NU * sxx, SIXY = 0.0}
  for i = 1, #v do
    local k = cmp[(i - 1) % #cmp + 1]
    near(v[i], exact[k], 1e-10 * sxx, what .. ': SIEF_ELGA ' .. k .. ' value ' .. i)
  end
end
for _, t in ipairs({0.5, 1.0, 2.0}) do
  check(RS, t, 'MECA_STATIQUE, INST ' .. t)
  check(RN, t, 'STAT_NON_LINE, INST ' .. t)
end
print('AFFE_CHAR_CINE_F: every check passed')
