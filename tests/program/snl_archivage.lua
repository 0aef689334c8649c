-- expect-exit: 0
-- expect-output: ARCHIVAGE: every check passed
-- STAT_NON_LINE's ARCHIVAGE on the unit square (one QUAD4, D_PLAN) pulled by forces F t at
-- P2 and P3 (sigma_xx = 2 F t, u_x = (1 - NU^2) / E 2 F t x), over 0, 0.1, ..., 1:
-- the stored instants are the initial one, those ARCHIVAGE asks for and the last one;
-- NUME_ORDRE counts the stored instants; each holds the closed-form displacement.
local E, NU, F = 200.0, 0.3, 1.5
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, x, y), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = F}}
RAMP = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
L48 = DEFI_LIST_REEL{VALE = {0.4, 0.8, 5.0}}
xyz = MA:getCoordinates()

local function run(archivage)
  return STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = RAMP}},
                       INCREMENT = {LIST_INST = L}, ARCHIVAGE = archivage}
end

for _, case in ipairs({
    {'every instant', nil, {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}},
    {'PAS_ARCH = 3', {PAS_ARCH = 3}, {0, 0.3, 0.6, 0.9, 1.0}},
    {'PAS_ARCH = 5', {PAS_ARCH = 5}, {0, 0.5, 1.0}},
    {'INST', {INST = {0.2, 0.5}}, {0, 0.2, 0.5, 1.0}},
    -- 5.0 is not computed: not stored; ABSOLU with PRECISION 1e-3 finds 0.4 and 0.8.
    {'LIST_INST', {LIST_INST = L48, CRITERE = 'ABSOLU', PRECISION = 1e-3}, {0, 0.4, 0.8, 1.0}},
    {'CHAM_EXCLU', {CHAM_EXCLU = {'SIEF_ELGA', 'FORC_NODA'}}, {0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0}},
  }) do
  local what, archivage, expected = case[1], case[2], case[3]
  local R = run(archivage)
  local p = R:getAccessParameters()
  if #p.INST ~= #expected then error(string.format('%s: %d instants stored, expected %d', what, #p.INST, #expected)) end
  for i, t in ipairs(expected) do
    near(p.INST[i], t, 1e-12, what .. ': INST of NUME_ORDRE ' .. (i - 1))
    if p.NUME_ORDRE[i] ~= i - 1 then error(what .. ': NUME_ORDRE ' .. p.NUME_ORDRE[i] .. ', expected ' .. (i - 1)) end
    local u = R:getField('DEPL', t):getValues()
    for n = 1, MA:getNumberOfNodes() do
      near(u[2 * n - 1], (1 - NU * NU) / E * 2 * F * t * xyz[3 * n - 2], 1e-14, what .. ': DX at INST ' .. t)
    end
  end
  -- The fields not excluded are stored (the excluded ones: snl_archivage_test_resu.lua).
  R:getField('REAC_NODA', 1.0)
  if what ~= 'CHAM_EXCLU' then
    R:getField('SIEF_ELGA', 1.0)
    R:getField('FORC_NODA', 1.0)
  end
end
print('ARCHIVAGE: every check passed')
