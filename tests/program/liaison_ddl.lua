-- expect-exit: 0
-- expect-output: LIAISON_DDL: every check passed
-- LIAISON_DDL u_x(N11) - u_x(N15) = d between the top corners of a block clamped at its
-- base (liaison_block.mail, D_PLAN). The reference is independent of the relations: by
-- superposition, the relation acts on the block as a pair of opposite forces +mu at N11,
-- -mu at N15, so u = mu u1 where u1 solves the block under the unit pair (FORCE_NODALE)
-- and mu = d / (u1_x(N11) - u1_x(N15)); the reactions of the relation (REAC_NODA) are
-- +mu and -mu. The relation is given by NOEUD in AFFE_CHAR_MECA, by GROUP_NO with
-- COEF_IMPO = d INST in AFFE_CHAR_MECA_F (instants 0.5 and 1), and solved by MECA_STATIQUE
-- and STAT_NON_LINE.
local d = 2e-3
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'liaison_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BASE = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
PAIR = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {{NOEUD = 'N11', FX = 1.0}, {GROUP_NO = 'HD', FX = -1.0}}}
REL = AFFE_CHAR_MECA{MODELE = MO, LIAISON_DDL = {NOEUD = {'N11', 'N15'}, DDL = {'DX', 'DX'}, COEF_MULT = {1.0, -1.0},
                                                  COEF_IMPO = d}}
DT = FORMULE{VALE = 'D * INST', D = d, NOM_PARA = 'INST'}
RELF = AFFE_CHAR_MECA_F{MODELE = MO, LIAISON_DDL = {GROUP_NO = {'HG', 'HD'}, DDL = {'DX', 'DX'},
                                                     COEF_MULT = {1.0, -1.0}, COEF_IMPO = DT}}
U1 = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BASE}, {CHARGE = PAIR}}, INST = 1.0}
RS = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BASE}, {CHARGE = REL}}, INST = 1.0}
LF = DEFI_LIST_REEL{VALE = {0.5, 1.0}}
RF = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BASE}, {CHARGE = RELF}}, LIST_INST = LF}
LN = DEFI_LIST_REEL{VALE = {0.0, 0.5, 1.0}}
RN = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BASE}, {CHARGE = RELF}},
                   COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = LN}}

local u1 = U1:getField('DEPL', 1.0):getValues()
local n11, n15 = 11, 15
local delta1 = u1[2 * n11 - 1] - u1[2 * n15 - 1]
local bottom = {}
for _, n in ipairs(MA:getNodes('BAS')) do bottom[n] = true end

local function check(res, t, what)
  local dt = d * t
  local mu = dt / delta1
  local u = res:getField('DEPL', t):getValues()
  local r = res:getField('REAC_NODA', t):getValues()
  near(u[2 * n11 - 1] - u[2 * n15 - 1], dt, 1e-15, what .. ': the relation')
  for i = 1, #u do near(u[i], mu * u1[i], 1e-10 * math.abs(dt), what .. ': DEPL value ' .. i) end
  near(r[2 * n11 - 1], mu, 1e-9 * math.abs(mu), what .. ': DX reaction at N11')
  near(r[2 * n15 - 1], -mu, 1e-9 * math.abs(mu), what .. ': DX reaction at N15')
  local sx, sy = 0.0, 0.0
  for n in pairs(bottom) do sx, sy = sx + r[2 * n - 1], sy + r[2 * n] end
  near(sx, 0.0, 1e-10 * math.abs(mu), what .. ': sum of the DX reactions on BAS')
  near(sy, 0.0, 1e-10 * math.abs(mu), what .. ': sum of the DY reactions on BAS')
end
check(RS, 1.0, 'AFFE_CHAR_MECA, MECA_STATIQUE')
check(RF, 0.5, 'AFFE_CHAR_MECA_F, MECA_STATIQUE, INST 0.5')
check(RF, 1.0, 'AFFE_CHAR_MECA_F, MECA_STATIQUE, INST 1')
check(RN, 0.5, 'AFFE_CHAR_MECA_F, STAT_NON_LINE, INST 0.5')
check(RN, 1.0, 'AFFE_CHAR_MECA_F, STAT_NON_LINE, INST 1')
print('LIAISON_DDL: every check passed')
