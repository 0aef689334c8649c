-- expect-exit: 0
-- expect-output: 23 Newton iterations, 23 factorizations.*linear solver MULT_FRONT.*23 Newton iterations, [1-5] factorizations.*linear solver GCPC.*conjugate gradient iterations over 23 solves.*GCPC: every check passed
-- SOLVEUR={METHODE='GCPC', PRE_COND='LDLT_SP' or 'LDLT_DP'}: the conjugate gradient
-- preconditioned by a factorization of an earlier tangent. The thick cylinder of
-- studies/thick_cylinder_hill.lua (elastic-perfectly plastic von Mises, plane strain, part 1:
-- internal pressure up to a plastic radius c = 1.5, 10 steps) solved with MULT_FRONT and with
-- GCPC: the same displacement to the Newton tolerance, and the stresses of GCPC's result
-- against Hill's solution within 0.5 % as in the study. tests/bad_input/snl_gcpc_*.lua: what
-- GCPC refuses.
DEBUT()
local A, B, E, NU, SY = 1.0, 2.0, 210000.0, 0.3, 240.0
local k = SY / math.sqrt(3)
local c = 1.5
local P1 = k * (1 - c * c / (B * B) + 2 * math.log(c / A))
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../studies/thick_cylinder_hill.mail'}
MA0 = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA0, MAILLAGE_NP1 = CO('MA1')}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA1, MAILLAGE_NP1 = CO('MA2')}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA2, MAILLAGE_NP1 = CO('MAIL')}
MODELE = AFFE_MODELE{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, ECRO_LINE = {D_SIGM_EPSI = 0.0, SY = SY}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
SYMETRIE = AFFE_CHAR_MECA{MODELE = MODELE, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
PRESSION = AFFE_CHAR_MECA{MODELE = MODELE, PRES_REP = {GROUP_MA = 'INT', PRES = P1}}
L10 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}

local RESI = 1e-9
local function solve(solveur)
  return STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT,
                       EXCIT = {{CHARGE = SYMETRIE}, {CHARGE = PRESSION, FONC_MULT = RAMPE}},
                       COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE'}, INCREMENT = {LIST_INST = L10},
                       CONVERGENCE = {RESI_GLOB_RELA = RESI}, SOLVEUR = solveur, INFO = 2}
end

local reference = solve({METHODE = 'MULT_FRONT'}):getField('DEPL', 1.0):getValues()
local scale = 0.0
for _, v in ipairs(reference) do scale = math.max(scale, math.abs(v)) end
if scale < 1e-4 then error('MULT_FRONT: no displacement') end
for _, pre in ipairs({'LDLT_SP', 'LDLT_DP'}) do
  RESU = solve({METHODE = 'GCPC', PRE_COND = pre})
  local u = RESU:getField('DEPL', 1.0):getValues()
  if #u ~= #reference then error(string.format('%d values, MULT_FRONT %d', #u, #reference)) end
  local worst = 0.0
  for i = 1, #u do worst = math.max(worst, math.abs(u[i] - reference[i])) end
  print(string.format('GCPC %s: largest difference with MULT_FRONT %.3e of the largest displacement', pre,
                      worst / scale))
  -- Two Newton solutions converged to RESI_GLOB_RELA: their difference is of that order.
  if not (worst <= 100 * RESI * scale) then error('GCPC ' .. pre .. ': not MULT_FRONT\'s solution') end
  RESU = CALC_CHAMP{reuse = RESU, RESULTAT = RESU, CONTRAINTE = 'SIGM_NOEU'}
  TEST_RESU{RESU = {
    {RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'A', NOM_CMP = 'SIXX',
     REFERENCE = 'ANALYTIQUE', VALE_REFE = -P1, VALE_CALC = -172.99907599766857, PRECISION = 0.005},
    {RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'A', NOM_CMP = 'SIYY',
     REFERENCE = 'ANALYTIQUE', VALE_REFE = -P1 + 2 * k, VALE_CALC = 104.17939577352215, PRECISION = 0.005},
    {RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'B', NOM_CMP = 'SIYY',
     REFERENCE = 'ANALYTIQUE', VALE_REFE = 2 * k * c * c / (B * B), VALE_CALC = 155.96258741799736, PRECISION = 0.005},
  }}
end
print('GCPC: every check passed')
FIN()
