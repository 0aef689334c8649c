-- expect-exit: 0
-- expect-output: BAR: every check passed
-- A bar under an end load, by MECA_STATIQUE and by STAT_NON_LINE PETIT. The distorted
-- QUAD8/TRIA6 patch of [0, 2] x [0, 2] (patch_quad8_tria6.mail), D_PLAN, E = 200, NU = 0.3,
-- clamped on GAUCHE (DX = DY = 0), a point force (FX, FY) at P3 = (2, 2): a problem
-- whose solution the elements do not reproduce exactly. Checks, independent of the
-- discretisation: the reactions on GAUCHE sum to -(FX, FY) (equilibrium of the body),
-- to 1e-10; FORC_NODA at P3 equals the applied force; STAT_NON_LINE PETIT with ELAS, a
-- linear problem, converges in one Newton iteration to the same displacements as
-- MECA_STATIQUE, to 1e-10 relative.
local E, NU, FX, FY = 200.0, 0.3, 1.5, -4.0
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, a, b), 2)
  end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_quad8_tria6.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = 'P3', FX = FX, FY = FY}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
                  SOLVEUR = {METHODE = 'UMFPACK'}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
N = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F, FONC_MULT = RAMPE}},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L},
                  CONVERGENCE = {RESI_GLOB_RELA = 1e-12}}

local left = {}
for _, n in ipairs(MA:getNodes('GAUCHE')) do left[n] = true end
local p3 = MA:getNodes('P3')[1]
local u = R:getField('DEPL', 0.0):getValues()
local r = R:getField('REAC_NODA', 0.0):getValues()
local f = R:getField('FORC_NODA', 0.0):getValues()
local rx, ry, umax = 0.0, 0.0, 0.0
for n = 1, MA:getNumberOfNodes() do
  if left[n] then rx, ry = rx + r[2 * n - 1], ry + r[2 * n] end
  umax = math.max(umax, math.abs(u[2 * n - 1]), math.abs(u[2 * n]))
end
near(rx, -FX, 1e-10 * math.abs(FY), 'sum of REAC_NODA DX on GAUCHE')
near(ry, -FY, 1e-10 * math.abs(FY), 'sum of REAC_NODA DY on GAUCHE')
near(f[2 * p3 - 1], FX, 1e-10 * math.abs(FY), 'FORC_NODA DX at P3')
near(f[2 * p3], FY, 1e-10 * math.abs(FY), 'FORC_NODA DY at P3')
if umax == 0.0 then error('no displacement') end

local iters = N:getAccessParameters().ITER_GLOB
if iters[2] ~= 1 then error('STAT_NON_LINE took ' .. iters[2] .. ' Newton iterations, expected 1') end
local un = N:getField('DEPL', 1.0):getValues()
for i = 1, #u do near(un[i], u[i], 1e-10 * umax, 'STAT_NON_LINE vs MECA_STATIQUE, DEPL value ' .. i) end
print('BAR: every check passed')
