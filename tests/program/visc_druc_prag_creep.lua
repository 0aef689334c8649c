-- expect-exit: 0
-- expect-output: VISC_DRUC_PRAG CREEP: every check passed
-- VISC_DRUC_PRAG, a triaxial creep test on one AXIS cell: lateral pressure PL on the
-- outer edge, axial pressure PA on the top, DY = 0 at the bottom, both held from the
-- first instant. The stress is the applied one at every instant (sigma_rr = sigma_tt =
-- -PL, sigma_yy = -PA), so with alpha, R and beta constant (their _0, _PIC and _ULT
-- values equal) the creep rate is constant, p_dot = A ((q + alpha I1 - R) / PREF)^N,
-- and p = p_dot t exactly, the implicit scheme included. The strains are Hooke's plus
-- p (3/2 s / q + beta 1): at the top outer corner (r = 1, y = 1) DX = eps_rr and
-- DY = eps_yy. Below the threshold (PA smaller) the cell stays elastic, INDIPLAS = 0.
local E, NU = 5000e6, 0.12
local A, N, PREF = 1e-7, 2.0, 1e6
local ALPHA, R, BETA = 0.1, 1e6, 0.05
local PL, PA = 5e6, 12e6

local function near(a, b, what)
  if not (math.abs(a - b) <= 1e-9 * math.abs(b)) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
local function value(res, field, t, component, index)
  local f = res:getField(field, t)
  local cmp, v = f:getComponents(), f:getValues()
  for i, c in ipairs(cmp) do
    if c == component then return v[(index - 1) * #cmp + i] end
  end
  error(field .. ' has no ' .. component)
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'visc_druc_prag_cell.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU},
                    VISC_DRUC_PRAG = {PREF = PREF, A = A, N = N, P_PIC = 0.5, P_ULT = 1.0,
                                      ALPHA_0 = ALPHA, ALPHA_PIC = ALPHA, ALPHA_ULT = ALPHA,
                                      R_0 = R, R_PIC = R, R_ULT = R, BETA_0 = BETA, BETA_PIC = BETA, BETA_ULT = BETA}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
SIDE = AFFE_CHAR_MECA{MODELE = MO, PRES_REP = {GROUP_MA = 'DROITE', PRES = PL}}
BOTTOM = AFFE_CHAR_MECA{MODELE = MO, FACE_IMPO = {GROUP_MA = 'BAS', DY = 0.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1000.0, NOMBRE = 10}}

local function run(pa)
  local top = AFFE_CHAR_MECA{MODELE = MO, PRES_REP = {GROUP_MA = 'HAUT', PRES = pa}}
  return STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = SIDE}, {CHARGE = top}, {CHARGE = BOTTOM}},
                       COMPORTEMENT = {RELATION = 'VISC_DRUC_PRAG', RESI_INTE_RELA = 1e-12},
                       INCREMENT = {LIST_INST = L}, CONVERGENCE = {RESI_GLOB_RELA = 1e-10}}
end

-- Creep: q = PA - PL, I1 = -PA - 2 PL, s_yy = -2/3 q, s_rr = q/3.
local q, i1 = PA - PL, -PA - 2 * PL
local rate = A * ((q + ALPHA * i1 - R) / PREF) ^ N
local U = run(PA)
for _, t in ipairs({100.0, 500.0, 1000.0}) do
  local p = rate * t
  local epsYY = (-PA + 2 * NU * PL) / E + p * (-1.0 + BETA)
  local epsRR = (-PL + NU * (PL + PA)) / E + p * (0.5 + BETA)
  near(value(U, 'DEPL', t, 'DX', 4), epsRR, 'DX of N4 at ' .. t)
  near(value(U, 'DEPL', t, 'DY', 4), epsYY, 'DY of N4 at ' .. t)
  for g = 1, 4 do
    near(value(U, 'VARI_ELGA', t, 'V1', g), p, 'EPSPEQ at ' .. t)
    near(value(U, 'VARI_ELGA', t, 'V2', g), 1.0, 'INDIPLAS at ' .. t)
    near(value(U, 'VARI_ELGA', t, 'V3', g), 1.0, 'POS at ' .. t)
    near(value(U, 'SIEF_ELGA', t, 'SIYY', g), -PA, 'SIYY at ' .. t)
    near(value(U, 'SIEF_ELGA', t, 'SIZZ', g), -PL, 'SIZZ at ' .. t)
  end
end

-- Below the threshold: q + alpha I1 - R < 0 for PA = 6.5e6 (q = 1.5e6, alpha I1 = -1.65e6).
local V = run(6.5e6)
near(value(V, 'DEPL', 1000.0, 'DY', 4), (-6.5e6 + 2 * NU * PL) / E, 'elastic DY of N4')
for g = 1, 4 do
  if value(V, 'VARI_ELGA', 1000.0, 'V2', g) ~= 0.0 then error('INDIPLAS: the elastic cell flowed') end
  if value(V, 'VARI_ELGA', 1000.0, 'V1', g) ~= 0.0 then error('EPSPEQ: the elastic cell flowed') end
end
print('VISC_DRUC_PRAG CREEP: every check passed')
