-- expect-exit: 0
-- expect-output: E = 2\.1E\+11: alpha_U = 3\.003235.*E = 1\.0E-09: alpha_U = 3\.003235
-- Contact is scale-free: SSNP150 B (studies/ssnp150b.lua: NU = 0.3, Saint
-- Venant-Kirchhoff) with DISCRETE contact and its default keywords, with
-- E = 2.1E11 and E = 1E-9 instead of 1. The manufactured displacement is the
-- same, so CALC_SOLU_MANU's loads (derived from the material) scale with E, and
-- the L2 errors of U on meshes 3 and 4 and their rate must be E = 1's to 1E-8
-- (this study with E = 1: 3.9106729627E-06, 4.8773936170E-07, 3.0032345820).
-- The multipliers' equations used to be gaps in metres next to forces, and
-- those of the nodes out of contact 1 next to stiffnesses of the order of E:
-- with E = 1E-9 Newton took RESI_GLOB_RELA = 2E-5 > 1E-6 for round-off (the 1s
-- set the stiffness scale) and mesh 4's error changed in its 6th digit.
-- Meshes 0 to 2 are only refined; the rates need meshes 3 and 4.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../meshes/ssnp150b.mail'}
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}, PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
MA = {[0] = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}}
for i = 1, 4 do
  MA[i] = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', GROUP_MA = 'SURFACE', MAILLAGE_N = MA[i - 1]}
end
for i = 3, 4 do
  MA[i] = MODI_MAILLAGE{reuse = MA[i], MAILLAGE = MA[i], ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}
end

-- L2 error of U at INST = 1 on mesh i with Young's modulus E.
local function error_u(i, E)
  local ACIER = DEFI_MATERIAU{ELAS = {E = E, NU = 0.3}}
  local MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                             DEFORMATION = 'GREEN_LAGRANGE', MAILLAGE = MA[i],
                             BORD = {{NOM = 'DROITE', NORMALE = {1, 0}}, {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                                     {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}
  local MO = AFFE_MODELE{MAILLAGE = MA[i], AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
  local RESU = STAT_NON_LINE{MODELE = MO,
    CHAM_MATER = AFFE_MATERIAU{MAILLAGE = MA[i], AFFE = {TOUT = 'OUI', MATER = ACIER}},
    EXCIT = {{CHARGE = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DX = UX, DY = UY}},
              FONC_MULT = RAMPE},
             {CHARGE = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_CONTOUR = {
                {GROUP_MA = 'DROITE', FX = MMS.DROITE.FX, FY = MMS.DROITE.FY},
                {GROUP_MA = 'GAUCHE', FX = MMS.GAUCHE.FX, FY = MMS.GAUCHE.FY},
                {GROUP_MA = 'BAS', FX = MMS.BAS.FX_T, FY = MMS.BAS.FY_T}}}, FONC_MULT = RAMPE},
             {CHARGE = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_INTERNE = {
                GROUP_MA = 'SURFACE', FX = MMS.FORCE_INTERNE.FX, FY = MMS.FORCE_INTERNE.FY}}, FONC_MULT = RAMPE},
             {CHARGE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}}}},
    CONTACT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'DISCRETE',
                           ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}},
    COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 100}}
  local U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL', INST = 1.0}
  return POST_ERREUR{OPTION = 'DEPL_ABSO', CHAM_GD = U, MODELE = MO, GROUP_MA = 'SURFACE', DX = UX, DY = UY}:get('ERREUR', 1)
end

local reference = {ERREUR_3 = 3.9106729627E-06, ERREUR_4 = 4.8773936170E-07, ALPHA_U = 3.0032345820}
for _, E in ipairs({2.1E11, 1.0E-9}) do
  local e3, e4 = error_u(3, E), error_u(4, E)
  local alpha = -math.log(e4 / e3) / math.log(2)
  print(string.format('E = %.1E: alpha_U = %.6f (|U - Uex| = %.10E, %.10E)', E, alpha, e3, e4))
  local T = CREA_TABLE{LISTE = {{PARA = 'ERREUR_3', LISTE_R = {e3}}, {PARA = 'ERREUR_4', LISTE_R = {e4}},
                                {PARA = 'ALPHA_U', LISTE_R = {alpha}}}}
  for _, para in ipairs({'ERREUR_3', 'ERREUR_4', 'ALPHA_U'}) do
    TEST_TABLE{TABLE = T, NOM_PARA = para, VALE_CALC = reference[para], REFERENCE = 'SOURCE_EXTERNE',
               VALE_REFE = reference[para], PRECISION = 1.0E-8, LEGENDE = string.format('%s E=%.0E', para, E)}
  end
  TEST_TABLE{TABLE = T, NOM_PARA = 'ALPHA_U', VALE_CALC = reference.ALPHA_U, REFERENCE = 'ANALYTIQUE',
             VALE_REFE = 3.0, PRECISION = 1.0E-2}
end
