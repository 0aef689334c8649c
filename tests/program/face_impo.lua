-- expect-exit: 0
-- expect-output: FACE_IMPO: every check passed
-- FACE_IMPO DNOR and DTAN on inclined edges: the unit square rotated by 30 degrees
-- (liaison_rotated_quad8.mail, 2 x 2 QUAD8, SEG3 edges), D_PLAN, E = 1000, NU = 0.3;
-- local axes e1 = (cos 30, sin 30), e2 = (-sin 30, cos 30), x1 = X.e1, x2 = X.e2.
-- 1. DNOR = 0 on GAUCHE (x1 = 0) and on BAS (x2 = 0) but its end O (SANS_GROUP_NO: O keeps
--    GAUCHE's condition alone), traction S e1 on DROITE: the
--    uniform uniaxial stress sigma = S e1 e1^T, u = eps1 x1 e1 + eps2 x2 e2 with
--    eps1 = (1 - NU^2) S / E, eps2 = -NU (1 + NU) S / E.
-- 2. AFFE_CHAR_MECA_F: DNOR = 0 on GAUCHE and BAS, DNOR = delta on DROITE, DTAN = -delta x1
--    on HAUT (the tangent of HAUT, walked counterclockwise, is -e1; a function of X, Y):
--    u1 = delta x1, u2 = -NU / (1 - NU) delta x2, sigma = E delta / (1 - NU^2) e1 e1^T.
--    At the corner of DROITE and HAUT both conditions say u1 = delta: redundant, accepted.
-- Linear fields: exact on the mesh (SIEF_ELGA to 1e-10, DEPL to 1e-12).
local E, NU, S, delta = 1000.0, 0.3, 4.0, 1e-3
local c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'liaison_rotated_quad8.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
local xyz = MA:getCoordinates()

local function check(res, eps1, eps2, sigma1, what)
  local u = res:getField('DEPL', 1.0):getValues()
  for n = 1, MA:getNumberOfNodes() do
    local X, Y = xyz[3 * n - 2], xyz[3 * n - 1]
    local x1, x2 = X * c + Y * s, -X * s + Y * c
    near(u[2 * n - 1], eps1 * x1 * c - eps2 * x2 * s, 1e-12, what .. ': DX of node ' .. n)
    near(u[2 * n], eps1 * x1 * s + eps2 * x2 * c, 1e-12, what .. ': DY of node ' .. n)
  end
  local sief = res:getField('SIEF_ELGA', 1.0)
  local cmp, v = sief:getComponents(), sief:getValues()
  local exact = {SIXX = sigma1 * c * c, SIYY = sigma1 * s * s, SIXY = sigma1 * s * c, SIZZ = NU * sigma1}
  for i = 1, #v do
    local k = cmp[(i - 1) % #cmp + 1]
    near(v[i], exact[k], 1e-10 * sigma1, what .. ': SIEF_ELGA ' .. k .. ' value ' .. i)
  end
end

CH1 = AFFE_CHAR_MECA{MODELE = MO, FACE_IMPO = {{GROUP_MA = 'GAUCHE', DNOR = 0.0},
                                               {GROUP_MA = 'BAS', SANS_GROUP_NO = 'O', DNOR = 0.0}},
                     FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = S * c, FY = S * s}}
R1 = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH1}, INST = 1.0}
check(R1, (1 - NU * NU) * S / E, -NU * (1 + NU) * S / E, S, 'traction')

ZERO = DEFI_CONSTANTE{VALE = 0.0}
DELTA = DEFI_CONSTANTE{VALE = delta}
TAN = FORMULE{VALE = '-D * (X * C + Y * S)', D = delta, C = c, S = s, NOM_PARA = {'X', 'Y'}}
CH2 = AFFE_CHAR_MECA_F{MODELE = MO, FACE_IMPO = {{GROUP_MA = 'GAUCHE', DNOR = ZERO}, {GROUP_MA = 'BAS', DNOR = ZERO},
                                                 {GROUP_MA = 'DROITE', DNOR = DELTA}, {GROUP_MA = 'HAUT', DTAN = TAN}}}
R2 = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH2}, INST = 1.0}
check(R2, delta, -NU / (1 - NU) * delta, E * delta / (1 - NU * NU), 'imposed DNOR and DTAN')
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R3 = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH2}, COMPORTEMENT = {RELATION = 'ELAS'},
                   INCREMENT = {LIST_INST = L1}}
check(R3, delta, -NU / (1 - NU) * delta, E * delta / (1 - NU * NU), 'imposed DNOR and DTAN, STAT_NON_LINE')
print('FACE_IMPO: every check passed')
