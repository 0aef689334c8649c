-- expect-exit: 0
-- expect-output: driver options: every check passed
-- STAT_NON_LINE's driver options on a bar whose response stiffens: the unit square (one
-- QUAD4, D_PLAN), Saint Venant-Kirchhoff (GROT_GDEP) with E = 1, NU = 0, pulled by a dead
-- traction P t on DROITE (nodal forces P/2 t at P2, P3; DX = 0 on GAUCHE, DY = 0 on BAS):
-- the stretch l is uniform and P t = l (l^2 - 1) / 2. From the tangent at rest the first
-- Newton step overshoots far. RECH_LINEAIRE (CORDE, MIXTE) converges in fewer iterations
-- than plain Newton, also with a linear relation. MIXTE with RHO_MAX = 1.5: with the
-- default 10 its first expansion, rho = 3, takes the bar near its collapse (l = 0.12),
-- where |f| is already below RESI_LINE_RELA |f(0)|, and Newton then stalls: f is no merit
-- function there. DEFI_LIST_INST's SUBD_METHODE='AUTO' cuts the step that fails with
-- ITER_GLOB_MAXI = 7; SOLVEUR METHODE='MUMPS' (Debian's MUMPS, with its own keywords) and
-- 'LDLT' solve too. Each gives the closed-form stretch.
local P = 20.0
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, x, y), 2) end
end
local function stretch(p)  -- the root of l (l^2 - 1) / 2 = p
  local l = 2.0
  for _ = 1, 100 do l = l - (l * (l * l - 1) / 2 - p) / ((3 * l * l - 1) / 2) end
  return l
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
PULL = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = P / 2}}
RAMP = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
AUTO = DEFI_LIST_INST{DEFI_LIST = {VALE = {0.0, 1.0}}, ECHEC = {SUBD_METHODE = 'AUTO', SUBD_PAS_MINI = 1e-3}}

local function run(list, options)
  local keys = {MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = PULL, FONC_MULT = RAMP}},
                COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, INCREMENT = {LIST_INST = list},
                CONVERGENCE = {RESI_GLOB_RELA = 1e-10, ITER_GLOB_MAXI = options.maxi or 30}}
  for k, v in pairs(options) do if k ~= 'maxi' then keys[k] = v end end  -- EXCIT too
  local R = STAT_NON_LINE(keys)
  local u = R:getField('DEPL', 1.0):getValues()
  near(u[3], stretch(P) - 1, 1e-8, 'DX of P2')  -- node N2 = P2
  local p = R:getAccessParameters()
  return p.ITER_GLOB[#p.ITER_GLOB], p
end

local plain = run(L, {})
local corde = run(L, {RECH_LINEAIRE = {}})
local mixte = run(L, {RECH_LINEAIRE = {METHODE = 'MIXTE', RHO_MAX = 1.5}})
if not (corde <= plain - 3) then error(string.format('CORDE: %d iterations, plain Newton %d', corde, plain)) end
if not (mixte < plain) then error(string.format('MIXTE: %d iterations, plain Newton %d', mixte, plain)) end
if run(L, {maxi = corde, RECH_LINEAIRE = {}}) ~= corde then error('CORDE with ITER_GLOB_MAXI = its count') end
-- With a linear relation (DROITE moves as one, LIAISON_UNIF DX: the solution already does)
-- the search runs along the corrections of the master unknowns.
UNIF = AFFE_CHAR_MECA{MODELE = MO, LIAISON_UNIF = {GROUP_MA = 'DROITE', DDL = 'DX'}}
local related = run(L, {RECH_LINEAIRE = {},
                        EXCIT = {{CHARGE = BC}, {CHARGE = UNIF}, {CHARGE = PULL, FONC_MULT = RAMP}}})
if not (related <= plain - 3) then error(string.format('CORDE with LIAISON_UNIF: %d iterations, plain Newton %d', related, plain)) end

-- The full step fails with 7 iterations; AUTO cuts it; only the instants of the list are stored.
local _, p = run(AUTO, {maxi = 7})
if #p.INST ~= 2 then error(#p.INST .. ' instants stored, expected 0 and 1') end

run(L, {SOLVEUR = {METHODE = 'MUMPS', RENUM = 'QAMD', PCENT_PIVOT = 30, GESTION_MEMOIRE = 'IN_CORE',
                   ELIM_LAGR = 'NON', NPREC = -1, RESI_RELA = 1e-6, MATR_DISTRIBUEE = 'OUI'}})
run(L, {SOLVEUR = {METHODE = 'MUMPS', RENUM = 'SCOTCH', TYPE_RESOL = 'NONSYM'}})
run(L, {SOLVEUR = {METHODE = 'LDLT'}})
run(L, {SOLVEUR = {METHODE = 'MULT_FRONT', RENUM = 'MD'}})
print('driver options: every check passed')
