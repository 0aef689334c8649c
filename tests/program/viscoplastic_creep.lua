-- expect-exit: 0
-- expect-output: VISCOPLASTIC CREEP: every check passed.*<I> checks: 12 OK, 0 NOOK
-- NORTON (ALGO_INTE='NEWTON_PERT') and LEMAITRE with UN_SUR_M = 0 (the same law) on one
-- QUAD4 in AXIS, the unit square (plastic_square.mail; X the radius, Y the axis), a bar
-- under a constant axial stress s: FORCE_CONTOUR FY = s on HAUT from the first instant,
-- DY = 0 on BAS, DX = 0 on GAUCHE (the axis), DROITE free, so s_rr = s_tt = 0. Norton's
-- creep under a constant stress is, by hand from d eps_v/dt = 3/2 (s_eq / K)^N s / s_eq:
--   eps_v = (s / K)^N t (-1/2, 1, -1/2, 0),   EPYY = s / E + (s / K)^N t,
-- and the implicit scheme (PARM_THETA = 1, the flow at the end of each step, where the
-- stress is s) reproduces it for any step. Checked at every Gauss point at each instant:
-- SIEF_ELGA, EPSP_ELGA and the internal variables (NORTON: V1-V4 EPSPXX...EPSPXY;
-- LEMAITRE: V1 EPSPEQ = (s / K)^N t), the top's DY, and by TEST_RESU.
local E, NU, N, K, S = 178600.0, 0.3, 9.7, 1290.0, 250.0
local rate = (S / K) ^ N
local times = {0.0, 10.0, 60.0, 360.0, 3600.0}

local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-8 * scale) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
local function checkField(res, name, t, ref, scale, what)
  local f = res:getField(name, t)
  local cmp, v = f:getComponents(), f:getValues()
  if #v < 4 * #cmp then error(what .. ' ' .. name .. ' has only ' .. #v .. ' values') end
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    if ref[c] ~= nil then near(v[i], ref[c], scale, what .. ' ' .. name .. ' at t=' .. t .. ': ' .. c .. ' value ' .. i) end
  end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, LEMAITRE = {N = N, UN_SUR_K = 1 / K, UN_SUR_M = 0.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = S}}
L = DEFI_LIST_REEL{VALE = times}

for _, relation in ipairs({{RELATION = 'NORTON', ALGO_INTE = 'NEWTON_PERT'}, {RELATION = 'LEMAITRE'}}) do
  relation.ITER_INTE_MAXI = 1000
  relation.RESI_INTE_RELA = 1e-10
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL}},
                          COMPORTEMENT = relation, INCREMENT = {LIST_INST = L},
                          CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}
  R = CALC_CHAMP{reuse = R, RESULTAT = R, DEFORMATION = {'EPSP_ELGA'}}
  local what = relation.RELATION
  for i = 2, #times do
    local t = times[i]
    local creep = rate * t
    checkField(R, 'SIEF_ELGA', t, {SIXX = 0.0, SIYY = S, SIZZ = 0.0, SIXY = 0.0}, S, what)
    checkField(R, 'EPSP_ELGA', t, {EPXX = -creep / 2, EPYY = creep, EPZZ = -creep / 2, EPXY = 0.0}, creep, what)
    local v = relation.RELATION == 'NORTON' and {V1 = -creep / 2, V2 = creep, V3 = -creep / 2, V4 = 0.0, V7 = 0.0}
              or {V1 = creep, V2 = 0.0}
    checkField(R, 'VARI_ELGA', t, v, creep, what)
    local top = R:getField('DEPL', t)
    near(top:getValues()[6], S / E + creep, creep, what .. ' DY of N3 at t=' .. t)
  end
  local last = rate * times[#times]
  local function ref(x) return {REFERENCE = 'ANALYTIQUE', VALE_REFE = x, VALE_CALC = x, PRECISION = 1e-8, CRITERE = 'RELATIF'} end
  local function occ(t, extra)
    for key, value in pairs({RESULTAT = R, INST = times[#times], MAILLE = 'M1'}) do t[key] = value end
    for key, value in pairs(extra) do t[key] = value end
    return t
  end
  TEST_RESU{RESU = {
    occ({NOM_CHAM = 'EPSP_ELGA', NOM_CMP = 'EPYY', POINT = 1}, ref(last)),
    occ({NOM_CHAM = 'EPSP_ELGA', NOM_CMP = 'EPXX', POINT = 4}, ref(-last / 2)),
    occ({NOM_CHAM = 'VARI_ELGA', NOM_CMP = relation.RELATION == 'NORTON' and 'V2' or 'V1', POINT = 2}, ref(last)),
    occ({NOM_CHAM = 'SIEF_ELGA', NOM_CMP = 'SIYY', POINT = 3}, ref(S)),
    {RESULTAT = R, INST = times[#times], NOM_CHAM = 'DEPL', NOM_CMP = 'DY', NOEUD = 'N3', REFERENCE = 'ANALYTIQUE',
     VALE_REFE = S / E + last, VALE_CALC = S / E + last, PRECISION = 1e-8, CRITERE = 'RELATIF'},
    occ({NOM_CHAM = 'SIEF_ELGA', NOM_CMP = 'SIXX', POINT = 1}, {REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, VALE_CALC = 0.0,
        ORDRE_GRANDEUR = S, CRITERE = 'ABSOLU', PRECISION = 1e-8 * S}),
  }}
end

-- Restarts: LEMAITRE with strain hardening (UN_SUR_M = 0.3), PARM_THETA = 0.5, D_PLAN, the
-- load ramped up then held; a run stopped at INST 360 and continued with ETAT_INIT
-- EVOL_NOLI (reuse), and one started from the fields of INST 360 (DEPL, SIGM, VARI), give
-- at INST 3600 what the uninterrupted run gives (the creep rate depends on p: restarting
-- without the variables would not).
MATH = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, LEMAITRE = {N = N, UN_SUR_K = 1 / K, UN_SUR_M = 0.3}}
CMH = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MATH}}
MOP = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
BCP = AFFE_CHAR_MECA{MODELE = MOP, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
PULLP = AFFE_CHAR_MECA{MODELE = MOP, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = S}}
RAMP = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 10.0, 1.0, 3600.0, 1.0}}
LH = DEFI_LIST_REEL{VALE = {0.0, 5.0, 10.0, 60.0, 360.0, 1000.0, 3600.0}}
local function run(extra)
  local k = {MODELE = MOP, CHAM_MATER = CMH, EXCIT = {{CHARGE = BCP}, {CHARGE = PULLP, FONC_MULT = RAMP}},
             COMPORTEMENT = {RELATION = 'LEMAITRE', PARM_THETA = 0.5, ITER_INTE_MAXI = 1000},
             INCREMENT = {LIST_INST = LH}}
  for key, value in pairs(extra or {}) do k[key] = value end
  return STAT_NON_LINE(k)
end
local RH = run()
local RS = run({INCREMENT = {LIST_INST = LH, INST_FIN = 360.0}})
RS = run({reuse = RS, ETAT_INIT = {EVOL_NOLI = RS}})
local U2 = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RH, NOM_CHAM = 'DEPL', INST = 360.0}
local S2 = CREA_CHAMP{TYPE_CHAM = 'ELGA_SIEF_R', OPERATION = 'EXTR', RESULTAT = RH, NOM_CHAM = 'SIEF_ELGA', INST = 360.0}
local V2 = CREA_CHAMP{TYPE_CHAM = 'ELGA_VARI_R', OPERATION = 'EXTR', RESULTAT = RH, NOM_CHAM = 'VARI_ELGA', INST = 360.0}
local RF = run({ETAT_INIT = {DEPL = U2, SIGM = S2, VARI = V2}, INCREMENT = {LIST_INST = LH, INST_INIT = 360.0}})
if not (RH:getField('VARI_ELGA', 3600.0):getValues()[1] > RH:getField('VARI_ELGA', 360.0):getValues()[1]) then
  error('LEMAITRE: no creep between INST 360 and 3600')
end
for _, name in ipairs({'DEPL', 'SIEF_ELGA', 'VARI_ELGA'}) do
  local a = RH:getField(name, 3600.0):getValues()
  for which, other in pairs({['EVOL_NOLI restart'] = RS, ['field restart'] = RF}) do
    local b = other:getField(name, 3600.0):getValues()
    if #a ~= #b then error(which .. ': ' .. name .. ' sizes differ') end
    for i = 1, #a do near(b[i], a[i], math.max(1.0, math.abs(a[i])), which .. ' ' .. name .. ' value ' .. i) end
  end
end
print('VISCOPLASTIC CREEP: every check passed')
