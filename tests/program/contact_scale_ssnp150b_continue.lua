-- expect-exit: 0
-- expect-output: alpha_U = 3\.00347.*alpha_p = 2\.80428
-- Contact is scale-free: SSNP150 B (studies/ssnp150b.lua: NU = 0.3, Saint
-- Venant-Kirchhoff, CONTINUE contact, here with its default keywords save
-- COEF_CONT) with E = 2.1E11 (Pa) instead of 1. COEF_CONT is absolute (a pressure
-- per unit gap, as code_aster's): the scaled study takes the default 100 times E,
-- the same problem as E = 1 with the default. The manufactured displacement is the same, so
-- CALC_SOLU_MANU's loads and the exact pressure (derived from ACIER) are 2.1E11
-- times larger: the L2 error of U and the error of the contact pressure over E
-- must be those found with E = 1 (docs/verification/ssnp150.md, POST_ERREUR
-- columns, meshes 3 and 4; the same to 7 digits with the default COEF_CONT =
-- 100 as with the study's 10), and so must the rates. It used to stop at the
-- first step ("numerically singular ... missing Dirichlet conditions?").
-- Meshes 0 to 2 are only refined; the rates need meshes 3 and 4.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../meshes/ssnp150b.mail'}
E = 2.1E11
ACIER = DEFI_MATERIAU{ELAS = {E = E, NU = 0.3}}
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                     DEFORMATION = 'GREEN_LAGRANGE', MAILLAGE = MA,
                     BORD = {{NOM = 'DROITE', NORMALE = {1, 0}}, {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                             {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}, PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
for i = 1, 3 do MA = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', GROUP_MA = 'SURFACE', MAILLAGE_N = MA} end
local errU, errP = {}, {}
for i = 3, 4 do
  MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
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
                           ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', COEF_CONT = 100.0 * E}},
    COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 100}}
  local U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL', INST = 1.0}
  errU[i] = POST_ERREUR{OPTION = 'DEPL_ABSO', CHAM_GD = U, MODELE = MO, GROUP_MA = 'SURFACE', DX = UX, DY = UY}:get('ERREUR', 1)
  errP[i] = POST_ERREUR{OPTION = 'LAGR_ABSO', CHAM_GD = U, MODELE = MO, GROUP_MA = 'BAS',
                        LAGS_C = MMS.BAS.PRES}:get('ERREUR', 1) / E
  print(string.format('mesh %d: |U - Uex| = %.10e, |p - pex| / E = %.10e', i, errU[i], errP[i]))
  if i < 4 then MA = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', GROUP_MA = 'SURFACE', MAILLAGE_N = MA} end
end
local alphaU = -math.log(errU[4] / errU[3]) / math.log(2)
local alphaP = -math.log(errP[4] / errP[3]) / math.log(2)
print(string.format('alpha_U = %.6f, alpha_p = %.6f', alphaU, alphaP))
T = CREA_TABLE{LISTE = {{PARA = 'ERREUR_U_3', LISTE_R = {errU[3]}}, {PARA = 'ERREUR_U_4', LISTE_R = {errU[4]}},
                        {PARA = 'ERREUR_P_3', LISTE_R = {errP[3]}}, {PARA = 'ERREUR_P_4', LISTE_R = {errP[4]}},
                        {PARA = 'ALPHA_U', LISTE_R = {alphaU}}, {PARA = 'ALPHA_P', LISTE_R = {alphaP}}}}
-- E = 1's values (docs/verification/ssnp150.md), to their 7 printed digits.
for _, ref in ipairs({{'ERREUR_U_3', 3.911667E-06}, {'ERREUR_U_4', 4.877813E-07}, {'ERREUR_P_3', 7.030981E-06},
                      {'ERREUR_P_4', 1.006568E-06}, {'ALPHA_U', 3.003477}, {'ALPHA_P', 2.804282}}) do
  TEST_TABLE{TABLE = T, NOM_PARA = ref[1], VALE_CALC = ref[2], REFERENCE = 'SOURCE_EXTERNE', VALE_REFE = ref[2],
             PRECISION = 1.0E-6, LEGENDE = ref[1]}
end
TEST_TABLE{TABLE = T, NOM_PARA = 'ALPHA_U', VALE_CALC = 3.003477, REFERENCE = 'ANALYTIQUE', VALE_REFE = 3.0,
           PRECISION = 1.0E-2}
