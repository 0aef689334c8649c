-- expect-exit: 0
-- expect-output: ELAS_HYPER UNIAXIAL STRAIN: every check passed
-- ELAS_HYPER through DEFI_MATERIAU and STAT_NON_LINE (GROT_GDEP, D_PLAN) on one QUAD4, the
-- unit square (plastic_square.mail), stretched along Y with DX = 0 on GAUCHE and DROITE:
-- F = diag(1, lambda, 1) at every point, lambda = 1.1, 1.2, 1.3. Reference: the stored
-- energy written with the principal stretches l1, l2, l3 (J = l1 l2 l3, I1 = sum l_i^2,
-- I2 = l1^2 l2^2 + l2^2 l3^2 + l3^2 l1^2, I1~ = J^(-2/3) I1, I2~ = J^(-4/3) I2)
--   W = C10 (I1~ - 3) + C01 (I2~ - 3) + C20 (I1~ - 3)^2 + K/2 (J - 1)^2,
-- whose Cauchy principal stresses are sigma_i = l_i dW/dl_i / J, differentiated here by
-- central differences (step 1e-4: an error of order 1e-8 relative). Checked: SIXX, SIYY,
-- SIZZ at every Gauss point, with K given, and with NU given instead (code_aster's
-- K = 4 (C10 + C01) (1 + NU) / (3 (1 - 2 NU))), which must give the same stresses.
local C10, C01, C20, K = 1.0, 0.3, 0.05, 50.0
local NU = (3 * K - 4 * (C10 + C01)) / (6 * K + 4 * (C10 + C01))  -- the NU whose K is 50

local function W(l1, l2, l3)
  local J = l1 * l2 * l3
  local I1 = l1 * l1 + l2 * l2 + l3 * l3
  local I2 = l1 * l1 * l2 * l2 + l2 * l2 * l3 * l3 + l3 * l3 * l1 * l1
  local I1b, I2b = J ^ (-2 / 3) * I1, J ^ (-4 / 3) * I2
  return C10 * (I1b - 3) + C01 * (I2b - 3) + C20 * (I1b - 3) ^ 2 + K / 2 * (J - 1) ^ 2
end
local function cauchy(l)
  local h, J = 1e-4, l[1] * l[2] * l[3]
  local s = {}
  for i = 1, 3 do
    local plus, minus = {l[1], l[2], l[3]}, {l[1], l[2], l[3]}
    plus[i], minus[i] = l[i] + h, l[i] - h
    s[i] = l[i] * (W(plus[1], plus[2], plus[3]) - W(minus[1], minus[2], minus[3])) / (2 * h) / J
  end
  return {SIXX = s[1], SIYY = s[2], SIZZ = s[3], SIXY = 0.0}
end
local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-6 * scale) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = {'GAUCHE', 'DROITE'}, DX = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DY = 1.0}}
STRETCH = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 3.0, 0.3}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0, 2.0, 3.0}}
for _, elastic in ipairs({{C10 = C10, C01 = C01, C20 = C20, K = K}, {C10 = C10, C01 = C01, C20 = C20, NU = NU}}) do
  local MAT = DEFI_MATERIAU{ELAS_HYPER = elastic}
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = STRETCH}},
                          COMPORTEMENT = {RELATION = 'ELAS_HYPER', DEFORMATION = 'GROT_GDEP'},
                          INCREMENT = {LIST_INST = L}, CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
  for _, t in ipairs({1.0, 2.0, 3.0}) do
    local ref = cauchy({1.0, 1.0 + 0.1 * t, 1.0})
    local f = R:getField('SIEF_ELGA', t)
    local cmp, v = f:getComponents(), f:getValues()
    if #v ~= 16 then error('SIEF_ELGA has ' .. #v .. ' values') end
    for i = 1, #v do
      local c = cmp[(i - 1) % #cmp + 1]
      near(v[i], ref[c], math.abs(ref.SIYY), (elastic.K and 'K' or 'NU') .. ' at t=' .. t .. ': ' .. c .. ' value ' .. i)
    end
  end
end
print('ELAS_HYPER UNIAXIAL STRAIN: every check passed')
