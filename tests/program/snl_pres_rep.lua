-- expect-exit: 0
-- expect-output: PRES_REP: every check passed
-- PRES_REP at command level, against exact homogeneous solutions. The unit square
-- (one QUAD4, edges oriented outwards: VERI_NORM's check passes), D_PLAN,
-- E = 200, NU = 0.3, DX = 0 on GAUCHE, DY = 0 on BAS, a pressure q on HAUT.
-- 1. PETIT: sigma_yy = -q, sigma_xx = 0, sigma_zz = -NU q;
--    u_x = NU (1 + NU) q / E x, u_y = -(1 - NU^2) q / E y; reactions on BAS sum to +q.
-- 2. GROT_GDEP (Saint Venant-Kirchhoff), homogeneous x = l1 X, y = l2 Y. With
--    E_ii = (l_i^2 - 1) / 2 and the free side, S11 = 0 gives E11 = -NU / (1 - NU) E22
--    and S22 = E / (1 - NU^2) E22. Chosen l2 = 0.8 (20 % shortening), the pressure is
--    derived by hand: follower (TYPE_CHARGE='SUIV', on the deformed top of length
--    l1): Cauchy sigma_22 = (l2 / l1) S22 = -q; dead (FIXE_CSTE, on the reference
--    top): P22 = l2 S22 = -q. Either load must give back l1, l2 exactly, SIEF_ELGA
--    (the Cauchy stress F S F^T / J, as code_aster) sigma_11 = 0,
--    sigma_22 = (l2 / l1) S22, and FORC_NODA DY summing over HAUT to the applied
--    force, -q l1 (follower) or -q (dead).
-- 3. VERI_NORM = 'NON' on tests/bad_input/base.mail, whose HAUT edges are walked
--    left to right (normal into the body): no check, and the pressure pulls, as
--    each edge's own normal says: sigma_yy = +q.
local E, NU = 200.0, 0.3
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, a, b), 2)
  end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
xyz = MA:getCoordinates()

local function checkDepl(R, ux, uy, what)
  local u = R:getField('DEPL', 1.0):getValues()
  for n = 1, MA:getNumberOfNodes() do
    near(u[2 * n - 1], ux * xyz[3 * n - 2], 1e-12, what .. ' DX of node ' .. n)
    near(u[2 * n], uy * xyz[3 * n - 1], 1e-12, what .. ' DY of node ' .. n)
  end
end
local function sumOver(R, field, group, component)
  local v, s = R:getField(field, 1.0):getValues(), 0.0
  for _, n in ipairs(MA:getNodes(group)) do s = s + v[2 * n - 2 + component] end
  return s
end

-- 1. Small strain.
local q = 3.0
PRES = AFFE_CHAR_MECA{MODELE = MO, PRES_REP = {GROUP_MA = 'HAUT', PRES = q}}
L1 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
R1 = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PRES}},
                   COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L1}}
checkDepl(R1, NU * (1 + NU) * q / E, -(1 - NU * NU) * q / E, 'PETIT')
for g, s in ipairs(R1:getField('SIEF_ELGA', 1.0):getValues()) do
  near(s, ({0.0, -q, -NU * q, 0.0})[(g - 1) % 4 + 1], 1e-12, 'PETIT SIEF_ELGA value ' .. g)
end
near(sumOver(R1, 'REAC_NODA', 'BAS', 2), q, 1e-12, 'PETIT reactions on BAS')

-- 2. Saint Venant-Kirchhoff, follower and dead pressure.
local l2 = 0.8
local E22 = (l2 * l2 - 1) / 2
local E11 = -NU / (1 - NU) * E22
local l1 = math.sqrt(1 + 2 * E11)
local S22 = E / (1 - NU * NU) * E22
local qFollower, qDead = -(l2 / l1) * S22, -l2 * S22
L5 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 5}}
-- NEWTON MATR_RIGI_SYME='OUI' solves with the symmetric part of the follower load's
-- unsymmetric tangent: other iterates, the same converged state.
for _, case in ipairs({{'SUIV', qFollower, l1, 'NON'}, {'FIXE_CSTE', qDead, 1.0, 'NON'}, {'SUIV', qFollower, l1, 'OUI'}}) do
  local kind, qq, length = case[1], case[2], case[3]
  local P = AFFE_CHAR_MECA{MODELE = MO, PRES_REP = {GROUP_MA = 'HAUT', PRES = qq}}
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, NEWTON = {MATR_RIGI_SYME = case[4]},
                          EXCIT = {{CHARGE = BC}, {CHARGE = P, FONC_MULT = RAMPE, TYPE_CHARGE = kind}},
                          COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
                          CONVERGENCE = {RESI_GLOB_RELA = 1e-12, ITER_GLOB_MAXI = 30}, INCREMENT = {LIST_INST = L5}}
  checkDepl(R, l1 - 1, l2 - 1, 'GROT_GDEP ' .. kind)
  for g, s in ipairs(R:getField('SIEF_ELGA', 1.0):getValues()) do
    if (g - 1) % 4 == 0 then near(s, 0.0, 1e-9, kind .. ' sigma_11 at value ' .. g) end
    if (g - 1) % 4 == 1 then near(s, l2 / l1 * S22, 1e-9, kind .. ' sigma_22 at value ' .. g) end
  end
  near(sumOver(R, 'FORC_NODA', 'HAUT', 2), -qq * length, 1e-9, kind .. ' FORC_NODA DY over HAUT')
  near(sumOver(R, 'REAC_NODA', 'BAS', 2), qq * length, 1e-9, kind .. ' reactions on BAS')
end

-- 3. VERI_NORM = 'NON' keeps each edge's normal: on base.mail's reversed HAUT, q pulls.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 21, FICHIER = '../bad_input/base.mail'}
MB = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 21}
MOB = AFFE_MODELE{MAILLAGE = MB, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CMB = AFFE_MATERIAU{MAILLAGE = MB, AFFE = {TOUT = 'OUI', MATER = MAT}}
BCB = AFFE_CHAR_MECA{MODELE = MOB, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
PB = AFFE_CHAR_MECA{MODELE = MOB, VERI_NORM = 'NON', PRES_REP = {GROUP_MA = 'HAUT', PRES = q}}
RB = STAT_NON_LINE{MODELE = MOB, CHAM_MATER = CMB, EXCIT = {{CHARGE = BCB}, {CHARGE = PB}},
                   COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L1}}
local xb, u = MB:getCoordinates(), RB:getField('DEPL', 1.0):getValues()
for n = 1, MB:getNumberOfNodes() do
  near(u[2 * n - 1], -NU * (1 + NU) * q / E * xb[3 * n - 2], 1e-12, 'VERI_NORM=NON DX of node ' .. n)
  near(u[2 * n], (1 - NU * NU) * q / E * xb[3 * n - 1], 1e-12, 'VERI_NORM=NON DY of node ' .. n)
end
print('PRES_REP: every check passed')
