-- SSNP150 modelization A: method of manufactured solutions for 2D contact in
-- large deformations (code_aster verification test V6.03.150).
-- Unit square, plane strain, Saint Venant-Kirchhoff, E = 1, NU = 0.3; the bottom
-- edge BAS is pressed onto the fixed parabolic master MAITRE,
-- Y = -0.05 (X - 0.5)^2 (one SEG3); DISCRETE (node-to-segment) contact.
-- Mesh: 256 QUAD8 + 65 SEG3, read from MED (built from meshes/ssnp150.geo, N = 16).
DEBUT{CODE = {NIV_PUB_WEB = 'INTERNET'}}

MAIL = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
MAIL = MODI_MAILLAGE{reuse = MAIL, MAILLAGE = MAIL,
                     ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}

MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                     AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}

ACIER = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}

-- The exact displacement (X, Y: reference coordinates).
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}

-- Body force, tractions and contact pressure that make it a solution: derived
-- exactly from UX, UY (the reference study pastes sympy output here).
MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                     DEFORMATION = 'GROT_GDEP', MAILLAGE = MAIL,
                     BORD = {{NOM = 'DROITE', NORMALE = {1, 0}},
                             {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                             {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}

RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1},
                      PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}

DEPL_IMP = AFFE_CHAR_MECA_F{MODELE = MODELE, DDL_IMPO = {GROUP_MA = 'HAUT', DX = UX, DY = UY}}
FORC_SUR = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_CONTOUR = {
  {GROUP_MA = 'DROITE', FX = MMS.DROITE.FX, FY = MMS.DROITE.FY},
  {GROUP_MA = 'GAUCHE', FX = MMS.GAUCHE.FX, FY = MMS.GAUCHE.FY},
  {GROUP_MA = 'BAS', FX = MMS.BAS.FX_T, FY = MMS.BAS.FY_T},  -- tangential part only
}}
FORC_VOL = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_INTERNE = {
  GROUP_MA = 'SURFACE', FX = MMS.FORCE_INTERNE.FX, FY = MMS.FORCE_INTERNE.FY}}
BLOCAGE = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}}

CONTACT = DEFI_CONTACT{MODELE = MODELE, FORMULATION = 'DISCRETE',
                       ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}

LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}

RESU = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT,
  EXCIT = {{CHARGE = DEPL_IMP, FONC_MULT = RAMPE},
           {CHARGE = FORC_SUR, FONC_MULT = RAMPE},
           {CHARGE = FORC_VOL, FONC_MULT = RAMPE},
           {CHARGE = BLOCAGE}},
  CONTACT = CONTACT,
  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
  INCREMENT = {LIST_INST = LINST},
  NEWTON = {REAC_ITER = 1},
  CONVERGENCE = {ITER_GLOB_MAXI = 100}}

-- DIFF = computed - exact displacement on the nodes of SURFACE, at INST = 1.
CHXN = CREA_CHAMP{TYPE_CHAM = 'NOEU_GEOM_R', OPERATION = 'EXTR', MAILLAGE = MAIL, NOM_CHAM = 'GEOMETRIE'}
UANA_F = CREA_CHAMP{TYPE_CHAM = 'NOEU_NEUT_F', OPERATION = 'AFFE', MAILLAGE = MAIL,
                    AFFE = {GROUP_MA = 'SURFACE', NOM_CMP = {'X1', 'X2'}, VALE_F = {UX, UY}}}
UANA = CREA_CHAMP{TYPE_CHAM = 'NOEU_NEUT_R', OPERATION = 'EVAL', CHAM_F = UANA_F, CHAM_PARA = CHXN}
UCALC = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL', INST = 1.0}
DIFF = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'ASSE', MAILLAGE = MAIL, ASSE = {
  {GROUP_MA = 'SURFACE', CHAM_GD = UCALC, NOM_CMP = {'DX', 'DY'}, CUMUL = 'OUI', COEF_R = 1.0},
  {GROUP_MA = 'SURFACE', CHAM_GD = UANA, NOM_CMP = {'X1', 'X2'}, NOM_CMP_RESU = {'DX', 'DY'},
   CUMUL = 'OUI', COEF_R = -1.0},
}}

-- Sum over the nodes and both components of |DIFF|: aster-lite's value, and the
-- reference code's (NON_REGRESSION there, 4.03888411513E-05) within 2 %.
TEST_RESU{CHAM_NO = {CHAM_GD = DIFF, TYPE_TEST = 'SOMM_ABS',
                     VALE_CALC = 4.0365713373585e-05,
                     REFERENCE = 'AUTRE_ASTER', VALE_REFE = 4.03888411513E-05, PRECISION = 0.02}}

IMPR_RESU{FORMAT = 'GMSH', RESU = {RESULTAT = RESU, NOM_CHAM = 'DEPL'}}

FIN{}
