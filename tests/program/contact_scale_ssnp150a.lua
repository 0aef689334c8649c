-- expect-exit: 0
-- Contact is scale-free: SSNP150 A (studies/ssnp150a.lua: 256 QUAD8, NU = 0.3,
-- Saint Venant-Kirchhoff) with E = 2.1E11 (Pa) instead of 1. The manufactured
-- displacement is the same, so CALC_SOLU_MANU's body force, tractions and
-- pressure (derived from ACIER) are 2.1E11 times larger and the computed
-- displacement must be the one found with E = 1: the sum over SURFACE's nodes of
-- |U - Uex| equals E = 1's to 1E-8 (the discretization error is 1E-3 of it),
-- with the default keywords of each formulation, save CONTINUE's COEF_CONT: it is
-- absolute (a pressure per unit gap, as code_aster's), so the scaled study takes
-- the default 100 times E to be the same problem as E = 1 with the default.
-- CONTINUE used to stop at the first step ("numerically singular ... missing
-- Dirichlet conditions?").
-- References (E = 1): DISCRETE, studies/ssnp150a.lua's value; CONTINUE, this
-- study with E = 1.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../studies/ssnp150a.med'}
MAIL = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
MAIL = MODI_MAILLAGE{reuse = MAIL, MAILLAGE = MAIL, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}
MODELE = AFFE_MODELE{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
E = 2.1E11
ACIER = DEFI_MATERIAU{ELAS = {E = E, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}
MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                     DEFORMATION = 'GROT_GDEP', MAILLAGE = MAIL,
                     BORD = {{NOM = 'DROITE', NORMALE = {1, 0}}, {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                             {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}, PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}
LOADS = {
  {CHARGE = AFFE_CHAR_MECA_F{MODELE = MODELE, DDL_IMPO = {GROUP_MA = 'HAUT', DX = UX, DY = UY}}, FONC_MULT = RAMPE},
  {CHARGE = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_CONTOUR = {
     {GROUP_MA = 'DROITE', FX = MMS.DROITE.FX, FY = MMS.DROITE.FY},
     {GROUP_MA = 'GAUCHE', FX = MMS.GAUCHE.FX, FY = MMS.GAUCHE.FY},
     {GROUP_MA = 'BAS', FX = MMS.BAS.FX_T, FY = MMS.BAS.FY_T}}}, FONC_MULT = RAMPE},
  {CHARGE = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_INTERNE = {
     GROUP_MA = 'SURFACE', FX = MMS.FORCE_INTERNE.FX, FY = MMS.FORCE_INTERNE.FY}}, FONC_MULT = RAMPE},
  {CHARGE = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}}}}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
CHXN = CREA_CHAMP{TYPE_CHAM = 'NOEU_GEOM_R', OPERATION = 'EXTR', MAILLAGE = MAIL, NOM_CHAM = 'GEOMETRIE'}
UANA_F = CREA_CHAMP{TYPE_CHAM = 'NOEU_NEUT_F', OPERATION = 'AFFE', MAILLAGE = MAIL,
                    AFFE = {GROUP_MA = 'SURFACE', NOM_CMP = {'X1', 'X2'}, VALE_F = {UX, UY}}}
UANA = CREA_CHAMP{TYPE_CHAM = 'NOEU_NEUT_R', OPERATION = 'EVAL', CHAM_F = UANA_F, CHAM_PARA = CHXN}

local reference = {DISCRETE = 4.0365713373585E-05, CONTINUE = 4.02859408815E-05}
for _, formulation in ipairs({'DISCRETE', 'CONTINUE'}) do
  local RESU = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = LOADS,
    CONTACT = DEFI_CONTACT{MODELE = MODELE, FORMULATION = formulation,
                           ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS',
                                   COEF_CONT = formulation == 'CONTINUE' and 100.0 * E or nil}},
    COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 100}}
  local UCALC = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL',
                           INST = 1.0}
  local DIFF = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'ASSE', MAILLAGE = MAIL, ASSE = {
    {GROUP_MA = 'SURFACE', CHAM_GD = UCALC, NOM_CMP = {'DX', 'DY'}, CUMUL = 'OUI', COEF_R = 1.0},
    {GROUP_MA = 'SURFACE', CHAM_GD = UANA, NOM_CMP = {'X1', 'X2'}, NOM_CMP_RESU = {'DX', 'DY'},
     CUMUL = 'OUI', COEF_R = -1.0}}}
  TEST_RESU{CHAM_NO = {CHAM_GD = DIFF, TYPE_TEST = 'SOMM_ABS', VALE_CALC = reference[formulation],
                       REFERENCE = 'SOURCE_EXTERNE', VALE_REFE = reference[formulation], PRECISION = 1.0E-8,
                       LEGENDE = formulation}}
end
