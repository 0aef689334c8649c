-- The mortar contact benchmark (bench/run --lac): SSNP150 (studies/ssnp150a.lua's
-- problem: manufactured solution, Saint Venant-Kirchhoff, E = 1, NU = 0.3, 10
-- increments) on meshes/ssnp150.geo's N x N QUAD8 grid (gmsh's .msh, bound to
-- unit 20 on the command line), with BAS pressed on the parabola MAITRE by
-- LAC contact (MODE = 'LAC'), or, for the time of the same mesh without
-- contact, with BAS loaded by the exact traction Pi.N that the contact
-- transmits (MODE = 'SANS'; bench/run sets MODE): the same unknowns but LAGS_C,
-- the same solution. Prints the L2 errors of U and of LAGS_C at the end.
MODE = 'LAC'
DEBUT()
MAIL = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
MAIL = MODI_MAILLAGE{reuse = MAIL, MAILLAGE = MAIL, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}
MODELE = AFFE_MODELE{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}
MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                     DEFORMATION = 'GROT_GDEP', MAILLAGE = MAIL,
                     BORD = {{NOM = 'DROITE', NORMALE = {1, 0}}, {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                             {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}, PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}
DEPL_IMP = AFFE_CHAR_MECA_F{MODELE = MODELE, DDL_IMPO = {GROUP_MA = 'HAUT', DX = UX, DY = UY}}
FORC_SUR = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_CONTOUR = {
  {GROUP_MA = 'DROITE', FX = MMS.DROITE.FX, FY = MMS.DROITE.FY},
  {GROUP_MA = 'GAUCHE', FX = MMS.GAUCHE.FX, FY = MMS.GAUCHE.FY},
  MODE == 'LAC' and {GROUP_MA = 'BAS', FX = MMS.BAS.FX_T, FY = MMS.BAS.FY_T}  -- tangential: contact gives the rest
                 or {GROUP_MA = 'BAS', FX = MMS.BAS.FX, FY = MMS.BAS.FY}}}
FORC_VOL = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_INTERNE = {
  GROUP_MA = 'SURFACE', FX = MMS.FORCE_INTERNE.FX, FY = MMS.FORCE_INTERNE.FY}}
BLOCAGE = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
local args = {MODELE = MODELE, CHAM_MATER = CHMAT,
  EXCIT = {{CHARGE = DEPL_IMP, FONC_MULT = RAMPE}, {CHARGE = FORC_SUR, FONC_MULT = RAMPE},
           {CHARGE = FORC_VOL, FONC_MULT = RAMPE}, {CHARGE = BLOCAGE}},
  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
  INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 30}}
if MODE == 'LAC' then
  args.CONTACT = DEFI_CONTACT{MODELE = MODELE, FORMULATION = 'CONTINUE',
                              ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'LAC'}}
end
RESU = STAT_NON_LINE(args)
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL', INST = 1.0}
EU = POST_ERREUR{OPTION = 'DEPL_ABSO', CHAM_GD = U, MODELE = MODELE, GROUP_MA = 'SURFACE', DX = UX, DY = UY}
print(string.format('L2 error of U: %.6e', EU:get('ERREUR', 1)))
if MODE == 'LAC' then
  EP = POST_ERREUR{OPTION = 'LAGR_ABSO', CHAM_GD = U, MODELE = MODELE, GROUP_MA = 'BAS', LAGS_C = MMS.BAS.PRES}
  print(string.format('L2 error of LAGS_C: %.6e', EP:get('ERREUR', 1)))
end
FIN()
