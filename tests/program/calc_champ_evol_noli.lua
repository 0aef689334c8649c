-- expect-exit: 0
-- expect-output: CALC_PATCH GROT_GDEP: every check passed
-- CALC_CHAMP on an evol_noli in large strain (STAT_NON_LINE, GROT_GDEP, ELAS: Saint
-- Venant-Kirchhoff), D_PLAN, E = 200, NU = 0.3, on the distorted QUAD8 patch: the
-- homogeneous deformation u = t H X, H = [[0.1, 0.05], [0.02, -0.04]], imposed on the
-- whole boundary (FONC_MULT t at the instants 0.5 and 1). At every point F = I + t H, the
-- Green-Lagrange strain E = (t (H + H^T) + t^2 H^T H) / 2, the linearized one
-- eps = t (H + H^T) / 2, and the second Piola-Kirchhoff stress S = lambda tr(E) I + 2 mu E
-- (E_zz = 0: S_zz = lambda tr(E)), lambda = E NU / ((1 + NU)(1 - 2 NU)), mu = E / (2 (1 + NU)).
-- SIEF_ELGA holds the Cauchy stress F S F^T / J (as code_aster in GROT_GDEP), and so do
-- SIGM_ELGA, SIGM_ELNO, SIGM_NOEU (on continuum elements code_aster's SIGM is SIEF). EPSG_* is E, EPSI_* is eps.
-- TOUT_ORDRE reaches the initial state NUME_ORDRE 0, unloaded: its reactions are zero.
-- NUME_ORDRE, INST and LIST_INST select instants.
local YOUNG, NU = 200.0, 0.3
local H = {{0.1, 0.05}, {0.02, -0.04}}
local lambda, mu = YOUNG * NU / ((1 + NU) * (1 - 2 * NU)), YOUNG / (2 * (1 + NU))

local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-10 * scale) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
local function exact(t)
  local h = {{t * H[1][1], t * H[1][2]}, {t * H[2][1], t * H[2][2]}}
  local function hth(i, j) return h[1][i] * h[1][j] + h[2][i] * h[2][j] end
  local eps = {EPXX = h[1][1], EPYY = h[2][2], EPZZ = 0.0, EPXY = 0.5 * (h[1][2] + h[2][1])}
  local gl = {EPXX = eps.EPXX + 0.5 * hth(1, 1), EPYY = eps.EPYY + 0.5 * hth(2, 2), EPZZ = 0.0,
              EPXY = eps.EPXY + 0.5 * hth(1, 2)}
  local tr = gl.EPXX + gl.EPYY
  local S = {{lambda * tr + 2 * mu * gl.EPXX, 2 * mu * gl.EPXY}, {2 * mu * gl.EPXY, lambda * tr + 2 * mu * gl.EPYY}}
  -- Cauchy: sigma = F S F^T / J, F = I + t H (F_zz = 1), sigma_zz = S_zz / J.
  local F = {{1 + h[1][1], h[1][2]}, {h[2][1], 1 + h[2][2]}}
  local J = F[1][1] * F[2][2] - F[1][2] * F[2][1]
  local function sigma(i, j)
    local v = 0.0
    for k = 1, 2 do for l = 1, 2 do v = v + F[i][k] * S[k][l] * F[j][l] end end
    return v / J
  end
  local s = {SIXX = sigma(1, 1), SIYY = sigma(2, 2), SIZZ = lambda * tr / J, SIXY = sigma(1, 2)}
  return s, eps, gl
end
local function checkField(res, name, t, ref, scale, minValues)
  local f = res:getField(name, t)
  local cmp, v = f:getComponents(), f:getValues()
  if #v < minValues then error(name .. ' has only ' .. #v .. ' values') end
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], ref[c], scale, name .. ' at t=' .. t .. ': ' .. c .. ' value ' .. i)
  end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_quad8.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = YOUNG, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
UX = FORMULE{VALE = 'A*X + B*Y', NOM_PARA = {'X', 'Y'}, A = H[1][1], B = H[1][2]}
UY = FORMULE{VALE = 'A*X + B*Y', NOM_PARA = {'X', 'Y'}, A = H[2][1], B = H[2][2]}
BC = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {GROUP_MA = {'BAS', 'DROITE', 'HAUT', 'GAUCHE'}, DX = UX, DY = UY}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{VALE = {0.0, 0.5, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC, FONC_MULT = RAMPE},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, INCREMENT = {LIST_INST = L},
                  CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, TOUT_ORDRE = 'OUI', CONTRAINTE = {'SIGM_ELGA', 'SIGM_ELNO', 'SIGM_NOEU'},
               FORCE = {'REAC_NODA', 'FORC_NODA'}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, NUME_ORDRE = {1, 2}, DEFORMATION = {'EPSG_ELGA', 'EPSG_NOEU'}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, INST = 1.0, DEFORMATION = {'EPSI_ELNO'}}
LI = DEFI_LIST_REEL{VALE = {0.5}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, LIST_INST = LI, DEFORMATION = {'EPSI_ELNO'}}
for _, t in ipairs({0.5, 1.0}) do
  local s, eps, gl = exact(t)
  local ss, es = math.abs(s.SIXX) + math.abs(s.SIYY), math.abs(gl.EPXX) + math.abs(gl.EPYY)
  checkField(R, 'SIEF_ELGA', t, s, ss, 4 * 36)
  checkField(R, 'SIGM_ELGA', t, s, ss, 4 * 36)
  checkField(R, 'SIGM_ELNO', t, s, ss, 4 * 32)
  checkField(R, 'SIGM_NOEU', t, s, ss, 4 * MA:getNumberOfNodes())
  checkField(R, 'EPSG_ELGA', t, gl, es, 4 * 36)
  checkField(R, 'EPSG_NOEU', t, gl, es, 4 * MA:getNumberOfNodes())
  checkField(R, 'EPSI_ELNO', t, eps, es, 4 * 32)
end
for i, r in ipairs(R:getField('REAC_NODA', 0.0):getValues()) do near(r, 0.0, 1.0, 'REAC_NODA at INST 0, value ' .. i) end
local s = exact(1.0)
TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'NC', NOM_CMP = 'SIZZ',
                  VALE_CALC = s.SIZZ, REFERENCE = 'ANALYTIQUE', VALE_REFE = s.SIZZ, PRECISION = 1e-10}}
print('CALC_PATCH GROT_GDEP: every check passed')
