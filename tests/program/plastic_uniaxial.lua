-- expect-exit: 0
-- expect-output: PLASTIC UNIAXIAL: every check passed.*<I> checks: 18 OK, 0 NOOK
-- VMIS_ISOT_LINE on one QUAD4, the unit square (plastic_square.mail), pulled along Y by
-- DDL_IMPO (DY = 0 on BAS, DX = 0 on GAUCHE, DY = e(t) on HAUT): e = 0.002, 0.004 (plastic
-- loading from the elastic limit 0.001) then 0.003 (elastic unloading), E = 200000,
-- NU = 0.3, ECRO_LINE D_SIGM_EPSI = ET = 2000, SY = 200. The state is homogeneous and
-- its closed form, derived by hand, is (RESI_INTE_RELA = 1e-14: the plane stress return
-- holds the yield condition to RESI_INTE_RELA x SY, as code_aster's):
--  * C_PLAN and AXIS (DROITE free: uniaxial stress, SIXX = SIZZ = 0): the hardening
--    slope in p is H = E ET / (E - ET); in loading e = s / E + p and s = SY + H p, so
--    p = (E e - SY) / (E + H); in unloading p stays and s drops by E de.
--  * D_PLAN with DX = 0 on DROITE too (uniaxial strain, EPXX = EPZZ = 0): the trial
--    von Mises stress is 2 mu e (mu = E / (2 (1 + NU))), so p = (2 mu e - SY) / (3 mu + H)
--    and q = SY + H p in loading, q drops by 2 mu de in unloading; with K = E / (3 (1 - 2 NU)),
--    SIYY = K e + 2 q / 3, SIXX = SIZZ = K e - q / 3.
-- In both, the flow is along the axis: EPSP = p (-1/2, 1, -1/2, 0) (EPXX, EPYY, EPZZ,
-- EPXY), V1 = p and V2 (INDIPLAS) = 1 in loading, 0 in unloading. Checked at every
-- Gauss point (SIEF_ELGA, VARI_ELGA, EPSP_ELGA), cell node (VARI_ELNO, EPSP_ELNO) and
-- node (VARI_NOEU, EPSP_NOEU) at each instant, and by TEST_RESU. Then the restarts: a run stopped at INST 2 and
-- continued with ETAT_INIT EVOL_NOLI (reuse), and one started from the fields of INST 2
-- (ETAT_INIT DEPL, SIGM, VARI), give at INST 3 what the uninterrupted run gives (the
-- unloading depends on the history: restarting from a zero stress would not).
local E, NU, ET, SY = 200000.0, 0.3, 2000.0, 200.0
local H = E * ET / (E - ET)
local mu, K = E / (2 * (1 + NU)), E / (3 * (1 - 2 * NU))
local strain = {[1.0] = 0.002, [2.0] = 0.004, [3.0] = 0.003}

local function exact(modelisation, t)
  local p2, s = nil, nil
  if modelisation == 'D_PLAN' then
    local function load(e) local p = (2 * mu * e - SY) / (3 * mu + H); return p, SY + H * p end
    local p, q = load(t == 3.0 and strain[2.0] or strain[t])
    if t == 3.0 then q = q + 2 * mu * (strain[3.0] - strain[2.0]) end
    local e = strain[t]
    s = {SIXX = K * e - q / 3, SIYY = K * e + 2 * q / 3, SIZZ = K * e - q / 3, SIXY = 0.0}
    p2 = p
  else
    local function load(e) local p = (E * e - SY) / (E + H); return p, SY + H * p end
    local p, sy = load(t == 3.0 and strain[2.0] or strain[t])
    if t == 3.0 then sy = sy + E * (strain[3.0] - strain[2.0]) end
    s = {SIXX = 0.0, SIYY = sy, SIZZ = 0.0, SIXY = 0.0}
    p2 = p
  end
  return s, {V1 = p2, V2 = t == 3.0 and 0.0 or 1.0}, {EPXX = -p2 / 2, EPYY = p2, EPZZ = -p2 / 2, EPXY = 0.0}
end

local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-9 * scale) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
local function checkField(res, name, t, ref, scale, count, what)
  local f = res:getField(name, t)
  local cmp, v = f:getComponents(), f:getValues()
  if #v ~= count then error(what .. ' ' .. name .. ' has ' .. #v .. ' values, expected ' .. count) end
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], ref[c], scale, what .. ' ' .. name .. ' at t=' .. t .. ': ' .. c .. ' value ' .. i)
  end
end
local function same(a, b, name, t, what)
  local va, vb = a:getField(name, t):getValues(), b:getField(name, t):getValues()
  if #va ~= #vb then error(what .. ': ' .. name .. ' sizes differ') end
  for i = 1, #va do near(vb[i], va[i], math.max(1.0, math.abs(va[i])), what .. ' ' .. name .. ' value ' .. i) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, ECRO_LINE = {D_SIGM_EPSI = ET, SY = SY}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
EPS = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 0.002, 2.0, 0.004, 3.0, 0.003}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0, 2.0, 3.0}}
local ONE = DEFI_CONSTANTE{VALE = 1.0}

for _, modelisation in ipairs({'D_PLAN', 'C_PLAN', 'AXIS'}) do
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = modelisation}}
  local fixed = {GROUP_MA = 'GAUCHE', DX = 0.0}
  if modelisation == 'D_PLAN' then fixed.GROUP_MA = {'GAUCHE', 'DROITE'} end
  local BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, fixed}}
  local PULL = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DY = 1.0}}
  local function run(extra)
    local k = {MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = EPS}},
               COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', RESI_INTE_RELA = 1e-14}, INCREMENT = {LIST_INST = L},
               CONVERGENCE = {RESI_GLOB_RELA = 1e-12}, INFO = 1}
    for key, value in pairs(extra or {}) do k[key] = value end
    return STAT_NON_LINE(k)
  end
  local R = run()
  R = CALC_CHAMP{reuse = R, RESULTAT = R, NUME_ORDRE = {1, 2, 3}, VARI_INTERNE = {'VARI_ELNO', 'VARI_NOEU'},
                 DEFORMATION = {'EPSP_ELGA', 'EPSP_ELNO', 'EPSP_NOEU'}}
  for _, t in ipairs({1.0, 2.0, 3.0}) do
    local s, v, ep = exact(modelisation, t)
    checkField(R, 'SIEF_ELGA', t, s, math.abs(s.SIYY), 16, modelisation)
    checkField(R, 'VARI_ELGA', t, v, 1e-3, 8, modelisation)
    checkField(R, 'VARI_ELNO', t, v, 1e-3, 8, modelisation)
    checkField(R, 'EPSP_ELGA', t, ep, 1e-3, 16, modelisation)
    checkField(R, 'EPSP_ELNO', t, ep, 1e-3, 16, modelisation)
    checkField(R, 'EPSP_NOEU', t, ep, 1e-3, 16, modelisation)
    checkField(R, 'VARI_NOEU', t, v, 1e-3, 8, modelisation)
  end
  local s3, v3, ep3 = exact(modelisation, 3.0)
  local function ref(x, scale) return {REFERENCE = 'ANALYTIQUE', VALE_REFE = x, VALE_CALC = x, PRECISION = 1e-9 * scale / math.max(math.abs(x), 1e-300), CRITERE = 'RELATIF'} end
  local function occ(t, extra)
    for key, value in pairs({RESULTAT = R, INST = 3.0, MAILLE = 'M1'}) do t[key] = value end
    for key, value in pairs(extra) do t[key] = value end
    return t
  end
  TEST_RESU{RESU = {
    occ({NOM_CHAM = 'SIEF_ELGA', NOM_CMP = 'SIYY', POINT = 1}, ref(s3.SIYY, math.abs(s3.SIYY))),
    occ({NOM_CHAM = 'VARI_ELGA', NOM_CMP = 'V1', POINT = 2}, ref(v3.V1, 1e-3)),
    occ({NOM_CHAM = 'VARI_ELNO', NOM_CMP = 'V1', NOEUD = 'N3'}, ref(v3.V1, 1e-3)),
    occ({NOM_CHAM = 'EPSP_ELGA', NOM_CMP = 'EPYY', POINT = 3}, ref(ep3.EPYY, 1e-3)),
    occ({NOM_CHAM = 'EPSP_ELNO', NOM_CMP = 'EPZZ', NOEUD = 'N1'}, ref(ep3.EPZZ, 1e-3)),
    occ({NOM_CHAM = 'VARI_ELGA', NOM_CMP = 'V2', POINT = 4}, {REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, VALE_CALC = 0.0, ORDRE_GRANDEUR = 1.0, CRITERE = 'ABSOLU', PRECISION = 1e-12}),
  }}

  -- Restart from the result: stopped at INST 2, continued to INST 3.
  local RS = run({INCREMENT = {LIST_INST = L, INST_FIN = 2.0}})
  RS = run({reuse = RS, ETAT_INIT = {EVOL_NOLI = RS}})
  for _, name in ipairs({'DEPL', 'SIEF_ELGA', 'VARI_ELGA'}) do same(R, RS, name, 3.0, modelisation .. ' EVOL_NOLI restart') end
  -- Restart from fields.
  local U2 = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'DEPL', INST = 2.0}
  local S2 = CREA_CHAMP{TYPE_CHAM = 'ELGA_SIEF_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', INST = 2.0}
  local V2 = CREA_CHAMP{TYPE_CHAM = 'ELGA_VARI_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'VARI_ELGA', INST = 2.0}
  local RF = run({ETAT_INIT = {DEPL = U2, SIGM = S2, VARI = V2}, INCREMENT = {LIST_INST = L, INST_INIT = 2.0}})
  for _, name in ipairs({'DEPL', 'SIEF_ELGA', 'VARI_ELGA'}) do same(R, RF, name, 3.0, modelisation .. ' field restart') end
end
print('PLASTIC UNIAXIAL: every check passed')
