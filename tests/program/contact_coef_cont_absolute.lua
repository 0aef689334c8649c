-- expect-exit: 0
-- DEFI_CONTACT COEF_CONT is a pressure per unit gap, used as given (as code_aster's,
-- not times Young's modulus). The block of contact_block.mail (2 x 2 QUAD8, D_PLAN,
-- small strain) in Pa, E = 1E9, NU = 0.3, pressed by p = 1E7 on its top against
-- the fixed MAITRE, CONTINUE contact with COEF_CONT = E (as SSNP152 G) and with
-- the default 100: the same exact solution, LAGS_C = RN = -p at every slave node,
-- JEU = 0, the top moving by -(1 - NU^2) p / E. COEF_CONT = E stopped at the first
-- step when it was taken relative to E (1E18: "numerically singular").
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../bad_input/contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
E, NU, P = 1.0E9, 0.3, 1.0E7
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
GAUCHE = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0}}
PRESS = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -P}}
FIXE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {GROUP_MA = {'MAITRE', 'MAITRE_BAS'}, DX = 0.0, DY = 0.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}

for _, coef in ipairs({E, 100.0}) do
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = GAUCHE}, {CHARGE = FIXE}, {CHARGE = PRESS}},
                          CONTACT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE',
                                                 ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS',
                                                         COEF_CONT = coef}},
                          COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L},
                          CONVERGENCE = {RESI_GLOB_RELA = 1e-10}, INFO = 1}
  for _, g in ipairs({'COIN', 'BAS_MIL', 'BAS_CEN'}) do
    TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'CONT_NOEU', GROUP_NO = g, NOM_CMP = 'RN',
                      VALE_CALC = -P, REFERENCE = 'ANALYTIQUE', VALE_REFE = -P, PRECISION = 1e-9}}
    TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'DEPL', GROUP_NO = g, NOM_CMP = 'LAGS_C',
                      VALE_CALC = -P, REFERENCE = 'ANALYTIQUE', VALE_REFE = -P, PRECISION = 1e-9}}
    TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'CONT_NOEU', GROUP_NO = g, NOM_CMP = 'JEU',
                      VALE_CALC = 0.0, CRITERE = 'ABSOLU', TOLE_MACHINE = 1e-14, ORDRE_GRANDEUR = 1.0,
                      REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0, PRECISION = 1e-14}}
  end
  TEST_RESU{RESU = {RESULTAT = R, INST = 1.0, NOM_CHAM = 'DEPL', GROUP_NO = 'HAUT_CEN', NOM_CMP = 'DY',
                    VALE_CALC = -(1 - NU * NU) * P / E, REFERENCE = 'ANALYTIQUE', VALE_REFE = -(1 - NU * NU) * P / E,
                    PRECISION = 1e-9}}
end
