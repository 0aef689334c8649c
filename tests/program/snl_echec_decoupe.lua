-- expect-exit: 2
-- expect-output: GAVE UP: <F> <STAT_NON_LINE> .*snl_echec_decoupe\.lua:[0-9]+: the instant 1\.000000E\+00 did not converge: no convergence in ITER_GLOB_MAXI = 2 Newton iterations \(RESI_GLOB_RELA = [0-9.E+-]+\) \(even after cutting the step 2 times\); 3 instant\(s\) were stored before the failure.*STOPPED: <F> <STAT_NON_LINE> .*the instant 1\.000000E\+00 did not converge: no convergence in ITER_GLOB_MAXI = 2 Newton iterations \(RESI_GLOB_RELA = [0-9.E+-]+\); 3 instant.*ECHEC: every check passed.*<A> <STAT_NON_LINE> instant 1\.000000E\+00: no convergence in ITER_GLOB_MAXI = 3 Newton iterations \(RESI_GLOB_RELA = [0-9.E+-]+\); the step \[0\.0000E\+00, 1\.0000E\+00\] is cut into 4 \(level 1\).*<A> <STAT_NON_LINE> instant 1\.000000E\+00: no convergence in ITER_GLOB_MAXI = 2 Newton iterations \(RESI_GLOB_RELA = [0-9.E+-]+\); the step \[5\.0000E-04, 1\.0000E\+00\] is cut into 2 \(level 1\).*<F> <LUA> the study went on after 2 fatal errors \(caught with pcall
-- The <F> the study catches with pcall still end the run with exit status 2.
-- DEFI_LIST_INST's ECHEC (SUBD_METHODE = 'MANUEL') through STAT_NON_LINE. The unit
-- square (one QUAD4), D_PLAN, GROT_GDEP, E = 200, NU = 0.3, DX = 0 on GAUCHE, DY = 0
-- on BAS, DX = a t on DROITE (a = 0.4): the exact homogeneous stretch x = l1 X,
-- y = l2 Y, l1 = 1 + a t, l2 = sqrt(1 - 2 NU / (1 - NU) E11), E11 = (l1^2 - 1) / 2.
-- Newton's relative residual falls like 0.35 e, 0.05 (0.35 e)^2, ... for a step of
-- stretch e (here measured: 1.4E-02, 1.1E-05, 6.1E-12 for e = 0.04).
-- 1. One step to t = 1 with ITER_GLOB_MAXI = 3 and RESI_GLOB_RELA = 1e-7 does not
--    converge (about 8e-5 at the third iteration); SUBD_PAS = 4 cuts it into steps
--    of stretch 0.1 that converge in 3 iterations (about 5e-9): an alarm (header of
--    this file), the exact answer at t = 1, and the result holds the instants of
--    the list (0 and 1).
-- 2. ITER_GLOB_MAXI = 2 and RESI_GLOB_RELA = 1e-8: steps of stretch 1e-4 converge
--    (residual about 1e-10 at the second iteration), but the step to t = 1, even cut
--    twice in two (steps of 0.1, residual about 1e-5), does not: STAT_NON_LINE
--    gives up with a <F> that names the instant, and the result (reuse=) keeps the
--    instants converged before: 0, 2.5e-4, 5e-4.
-- 3. ACTION = 'ARRET': the same failure stops at once, without cutting.
local E, NU, a = 200.0, 0.3, 0.4
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, x, y), 2)
  end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
ST = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'DROITE', DX = a}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
xyz = MA:getCoordinates()
local function keywords(list, convergence, extra)
  local k = {MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = ST, FONC_MULT = RAMPE}},
             COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}, CONVERGENCE = convergence,
             INCREMENT = {LIST_INST = list}}
  for key, v in pairs(extra or {}) do k[key] = v end
  return k
end
local function instants(R)
  local s = {}
  for _, t in ipairs(R:getAccessParameters().INST) do s[#s + 1] = string.format('%g', t) end
  return table.concat(s, ' ')
end

-- 1. Cut once, then converged.
LI1 = DEFI_LIST_INST{DEFI_LIST = {VALE = {0.0, 1.0}},
                     ECHEC = {EVENEMENT = 'ERREUR', ACTION = 'DECOUPE', SUBD_METHODE = 'MANUEL', SUBD_PAS = 4, SUBD_NIVEAU = 2}}
R1 = STAT_NON_LINE(keywords(LI1, {ITER_GLOB_MAXI = 3, RESI_GLOB_RELA = 1e-7}))
assert(instants(R1) == '0 1', 'instants of the cut run: ' .. instants(R1))
local l1 = 1 + a
local l2 = math.sqrt(1 - 2 * NU / (1 - NU) * (l1 * l1 - 1) / 2)
local u = R1:getField('DEPL', 1.0):getValues()
for n = 1, MA:getNumberOfNodes() do
  near(u[2 * n - 1], (l1 - 1) * xyz[3 * n - 2], 1e-7, 'cut run: DX of node ' .. n)
  near(u[2 * n], (l2 - 1) * xyz[3 * n - 1], 1e-7, 'cut run: DY of node ' .. n)
end

-- 2. Cut twice, then given up; the converged instants stay in the result.
LI2 = DEFI_LIST_INST{DEFI_LIST = {VALE = {0.0, 2.5e-4, 5e-4, 1.0}},
                     ECHEC = {SUBD_METHODE = 'MANUEL', SUBD_PAS = 2, SUBD_NIVEAU = 2}}
local conv = {ITER_GLOB_MAXI = 2, RESI_GLOB_RELA = 1e-8}
R2 = STAT_NON_LINE(keywords(LI2, conv, {INCREMENT = {LIST_INST = LI2, INST_FIN = 2.5e-4}}))
assert(instants(R2) == '0 0.00025', 'instants before the restart: ' .. instants(R2))
local ok, err = pcall(STAT_NON_LINE, keywords(LI2, conv, {reuse = R2, ETAT_INIT = {EVOL_NOLI = R2}}))
assert(not ok and type(err) == 'table' and err.aster_fatal, 'STAT_NON_LINE should have given up')
print('GAVE UP: ' .. err.aster_fatal)
assert(instants(R2) == '0 0.00025 0.0005', 'instants kept after the failure: ' .. instants(R2))
local l1b = 1 + a * 5e-4
u = R2:getField('DEPL', 5e-4):getValues()
for n = 1, MA:getNumberOfNodes() do near(u[2 * n - 1], (l1b - 1) * xyz[3 * n - 2], 1e-12, 'kept instant: DX of node ' .. n) end

-- 3. ACTION = 'ARRET': no cutting.
LI3 = DEFI_LIST_INST{DEFI_LIST = {VALE = {0.0, 2.5e-4, 5e-4, 1.0}}, ECHEC = {ACTION = 'ARRET'}}
ok, err = pcall(STAT_NON_LINE, keywords(LI3, conv))
assert(not ok and err.aster_fatal, 'ACTION=ARRET: STAT_NON_LINE should have stopped')
assert(not err.aster_fatal:find('cutting'), 'ACTION=ARRET cuts no step: ' .. err.aster_fatal)
print('STOPPED: ' .. err.aster_fatal)
print('ECHEC: every check passed')
