-- expect-exit: 0
-- expect-output: alpha_p = 2\.604
-- SSNP150 B as the reference code's older study had it: NU = 0 (the current
-- one has NU = 0.3, studies/ssnp150b.lua). Its results then were a MAX of DIFF
-- of 3.5625745143514E-07 on mesh 4 and alpha_p = 2.60378582: a second,
-- independent point where the CONTINUE contact (LAGS_C at every slave node)
-- and the error measures must agree with the reference code. Meshes 0 to 2 are
-- only refined; the rates need meshes 3 and 4.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../meshes/ssnp150b.mail'}
ACIER = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.0}}
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
                           ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', COEF_CONT = 10.0}},
    COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 100}}
  local UCALC = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL', INST = 1.0}
  errU[i] = POST_ERREUR{OPTION = 'DEPL_ABSO', CHAM_GD = UCALC, MODELE = MO, GROUP_MA = 'SURFACE',
                        DX = UX, DY = UY}:get('ERREUR', 1)
  errP[i] = POST_ERREUR{OPTION = 'LAGR_ABSO', CHAM_GD = UCALC, MODELE = MO, GROUP_MA = 'BAS',
                        LAGS_C = MMS.BAS.PRES}:get('ERREUR', 1)
  if i == 4 then
    local CHXN = CREA_CHAMP{TYPE_CHAM = 'NOEU_GEOM_R', OPERATION = 'EXTR', MAILLAGE = MA, NOM_CHAM = 'GEOMETRIE'}
    local UANA_F = CREA_CHAMP{TYPE_CHAM = 'NOEU_NEUT_F', OPERATION = 'AFFE', MAILLAGE = MA,
                              AFFE = {GROUP_MA = 'SURFACE', NOM_CMP = {'X1', 'X2'}, VALE_F = {UX, UY}}}
    local UANA = CREA_CHAMP{TYPE_CHAM = 'NOEU_NEUT_R', OPERATION = 'EVAL', CHAM_F = UANA_F, CHAM_PARA = CHXN}
    DIFF = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'ASSE', MAILLAGE = MA, ASSE = {
      {GROUP_MA = 'SURFACE', CHAM_GD = UCALC, NOM_CMP = {'DX', 'DY'}, CUMUL = 'OUI', COEF_R = 1.0},
      {GROUP_MA = 'SURFACE', CHAM_GD = UANA, NOM_CMP = {'X1', 'X2'}, NOM_CMP_RESU = {'DX', 'DY'},
       CUMUL = 'OUI', COEF_R = -1.0}}}
  else
    MA = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', GROUP_MA = 'SURFACE', MAILLAGE_N = MA}
  end
end
local alphaU = -math.log(errU[4] / errU[3]) / math.log(2)
local alphaP = -math.log(errP[4] / errP[3]) / math.log(2)
print(string.format('alpha_U = %.6f, alpha_p = %.6f', alphaU, alphaP))
RATES = CREA_TABLE{LISTE = {{PARA = 'ALPHA_U', LISTE_R = {alphaU}}, {PARA = 'ALPHA_P', LISTE_R = {alphaP}}}}
TEST_RESU{CHAM_NO = {CHAM_GD = DIFF, TYPE_TEST = 'MAX', VALE_CALC = 3.56302049712E-07,
                     REFERENCE = 'AUTRE_ASTER', VALE_REFE = 3.5625745143514E-07, PRECISION = 1.0E-3}}
TEST_TABLE{TABLE = RATES, NOM_PARA = 'ALPHA_U', VALE_CALC = 3.00370920536,
           REFERENCE = 'ANALYTIQUE', VALE_REFE = 3.0, PRECISION = 1.0E-2}
TEST_TABLE{TABLE = RATES, NOM_PARA = 'ALPHA_P', VALE_CALC = 2.60420685548,
           REFERENCE = 'AUTRE_ASTER', VALE_REFE = 2.60378582, PRECISION = 1.0E-3}
