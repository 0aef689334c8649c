-- expect-exit: 0
-- expect-output: LAC: the active set settles in one iteration
-- The active-set loop of STAT_NON_LINE (analysis/static_nonlinear.cpp,
-- settleStatuses): within a Newton iteration, LAC multipliers whose linearized
-- status is inactive are released and the correction solved again from the
-- same factorization, until the statuses hold for the linearized problem.
-- SSNP150's problem (bench/ssnp150_lac.lua's: Saint Venant-Kirchhoff, E = 1,
-- NU = 0.3, GROT_GDEP, 10 increments) on ssnp150b.mail refined four times
-- (16 x 16 QUAD8): the contact zone on BAS grows with the load, from the middle to
-- the whole of BAS at the sixth increment. Solved twice: with LAC on BAS, and
-- without contact, BAS loaded by the exact traction Pi.N the contact
-- transmits (the same solution, a smooth problem). What the loop guarantees:
-- each increment's prediction, made with the last increment's active set,
-- penetrates past the new zone; the first iteration activates every
-- penetrating multiplier (too many: each end of the zone overshoots by
-- several nodes), and its loop releases those the linearized problem puts in
-- tension, until none is left; from then on the active set holds (the
-- linearization's error is of second order) and Newton converges as on the
-- problem without contact. So at each instant LAC takes at most one
-- iteration more than the run without contact: the iteration that finds the
-- active set. Without the loop the semi-smooth Newton releases a node or two
-- at each end of the zone per iteration: here 4 4 4 4 5 3 3 3 3 3 iterations
-- against 3 at every instant without contact (5 at the fifth instant breaks
-- the bound); with it 4 3 3 3 3 3 3 3 3 3. On the 64 x 64 mesh of
-- bench/ssnp150_lac.lua: 6 to 9 per increment while the zone grows without
-- the loop, 4 with it, 3 without contact.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../meshes/ssnp150b.mail'}
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
for i = 1, 4 do MA = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', GROUP_MA = 'SURFACE', MAILLAGE_N = MA} end
MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = ACIER}}
MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                     DEFORMATION = 'GROT_GDEP', MAILLAGE = MA,
                     BORD = {{NOM = 'DROITE', NORMALE = {1, 0}}, {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                             {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}, PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
DEPL_IMP = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DX = UX, DY = UY}}
FORC_VOL = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_INTERNE = {
  GROUP_MA = 'SURFACE', FX = MMS.FORCE_INTERNE.FX, FY = MMS.FORCE_INTERNE.FY}}
BLOCAGE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}}
local function solve(lac)
  local FORC_SUR = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_CONTOUR = {
    {GROUP_MA = 'DROITE', FX = MMS.DROITE.FX, FY = MMS.DROITE.FY},
    {GROUP_MA = 'GAUCHE', FX = MMS.GAUCHE.FX, FY = MMS.GAUCHE.FY},
    lac and {GROUP_MA = 'BAS', FX = MMS.BAS.FX_T, FY = MMS.BAS.FY_T}  -- tangential: contact gives the rest
         or {GROUP_MA = 'BAS', FX = MMS.BAS.FX, FY = MMS.BAS.FY}}}
  local args = {MODELE = MO, CHAM_MATER = CHMAT,
    EXCIT = {{CHARGE = DEPL_IMP, FONC_MULT = RAMPE}, {CHARGE = FORC_SUR, FONC_MULT = RAMPE},
             {CHARGE = FORC_VOL, FONC_MULT = RAMPE}, {CHARGE = BLOCAGE}},
    COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 30}}
  if lac then
    args.CONTACT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE',
                                ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'LAC'}}
  end
  return STAT_NON_LINE(args):getAccessParameters().ITER_GLOB
end
local lac, smooth = solve(true), solve(false)
print('Newton iterations per instant, LAC:            ' .. table.concat(lac, ' '))
print('Newton iterations per instant, without contact: ' .. table.concat(smooth, ' '))
assert(#lac == 11 and #smooth == 11, 'ten instants and the initial state')
for i = 2, #lac do
  assert(lac[i] <= smooth[i] + 1, string.format('instant %d: LAC took %d iterations, %d without contact', i - 1,
                                                lac[i], smooth[i]))
end
print('LAC: the active set settles in one iteration')
