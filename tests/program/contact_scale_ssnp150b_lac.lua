-- expect-exit: 0
-- expect-output: LAC is scale-free
-- LAC (mortar) contact is scale-free: SSNP150 B's problem (studies/ssnp150b.lua:
-- NU = 0.3, Saint Venant-Kirchhoff) on its 64-QUAD8 mesh, solved with E = 1 and
-- with E = 2.1E11 (Pa). The manufactured displacement is the same, and
-- CALC_SOLU_MANU's loads and the exact pressure are E times larger: the L2
-- error of U, the error of the contact pressure over E and the Newton
-- iterations of every instant must be the same. The multipliers are stored
-- over the zone's stiffness scale and the status criterion is in units of E
-- (analysis/mortar_contact.cpp), so the iterates are the same up to round-off:
-- 1e-9 relative allows for the residual's round-off at RESI_GLOB_RELA = 1e-6
-- (Newton's last correction, of the order of the residual, is far smaller).
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../meshes/ssnp150b.mail'}
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
for i = 1, 3 do MA = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', GROUP_MA = 'SURFACE', MAILLAGE_N = MA} end
MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}, PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
local results = {}
for _, E in ipairs({1.0, 2.1E11}) do
  local ACIER = DEFI_MATERIAU{ELAS = {E = E, NU = 0.3}}
  local MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                             DEFORMATION = 'GREEN_LAGRANGE', MAILLAGE = MA,
                             BORD = {{NOM = 'DROITE', NORMALE = {1, 0}}, {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                                     {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}
  local RESU = STAT_NON_LINE{MODELE = MO,
    CHAM_MATER = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = ACIER}},
    EXCIT = {{CHARGE = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DX = UX, DY = UY}},
              FONC_MULT = RAMPE},
             {CHARGE = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_CONTOUR = {
                {GROUP_MA = 'DROITE', FX = MMS.DROITE.FX, FY = MMS.DROITE.FY},
                {GROUP_MA = 'GAUCHE', FX = MMS.GAUCHE.FX, FY = MMS.GAUCHE.FY},
                {GROUP_MA = 'BAS', FX = MMS.BAS.FX_T, FY = MMS.BAS.FY_T}}}, FONC_MULT = RAMPE},
             {CHARGE = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_INTERNE = {
                GROUP_MA = 'SURFACE', FX = MMS.FORCE_INTERNE.FX, FY = MMS.FORCE_INTERNE.FY}}, FONC_MULT = RAMPE},
             {CHARGE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}}}},
    CONTACT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE',
                           ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'LAC'}},
    COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 30}}
  local U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL', INST = 1.0}
  local r = {}
  r.u = POST_ERREUR{OPTION = 'DEPL_ABSO', CHAM_GD = U, MODELE = MO, GROUP_MA = 'SURFACE', DX = UX, DY = UY}:get('ERREUR', 1)
  r.p = POST_ERREUR{OPTION = 'LAGR_ABSO', CHAM_GD = U, MODELE = MO, GROUP_MA = 'BAS',
                    LAGS_C = MMS.BAS.PRES}:get('ERREUR', 1) / E
  r.iterations = RESU:getAccessParameters().ITER_GLOB
  print(string.format('E = %g: |U - Uex| = %.10e, |p - pex| / E = %.10e, Newton iterations %s', E, r.u, r.p,
                      table.concat(r.iterations, ' ')))
  results[#results + 1] = r
end
local a, b = results[1], results[2]
assert(math.abs(a.u - b.u) <= 1e-9 * a.u, 'the L2 error of U differs')
assert(math.abs(a.p - b.p) <= 1e-9 * a.p, 'the error of the pressure over E differs')
assert(table.concat(a.iterations, ' ') == table.concat(b.iterations, ' '), 'the Newton iterations differ')
print('LAC is scale-free')
