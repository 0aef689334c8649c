-- The creep benchmark (bench/run): the quarter of a thick cylinder of
-- thick_cylinder.lua (a = 1, b = 2, plane strain, QUAD8; mesh: bench/thick_cylinder.py,
-- bound to unit 20 on the command line), elastic with Norton creep (LEMAITRE with
-- UN_SUR_M = 0: d eps_v/dt = 3/2 (s_eq / K)^N s / s_eq), under an internal pressure
-- applied at the first instant and held to T = 1000, in 20 increments of the implicit
-- scheme (NEWTON_PERT: PARM_THETA = 1, consistent tangent); prints the radial
-- displacement of the inner point A at the end.
DEBUT()
MAIL = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                     AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = 210000.0, NU = 0.3}, LEMAITRE = {N = 4.0, UN_SUR_K = 3e-4, UN_SUR_M = 0.0}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
CHAR = AFFE_CHAR_MECA{MODELE = MODELE,
                      DDL_IMPO = {{GROUP_NO = 'BAS', DY = 0.0}, {GROUP_NO = 'GAUCHE', DX = 0.0}},
                      PRES_REP = {GROUP_MA = 'INT', PRES = 100.0}}
TEMPS = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1000.0, NOMBRE = 20}}
RESU = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {CHARGE = CHAR},
                     COMPORTEMENT = {RELATION = 'NORTON', ALGO_INTE = 'NEWTON_PERT'},
                     INCREMENT = {LIST_INST = TEMPS}}
IMPR_RESU{FORMAT = 'RESULTAT', RESU = {RESULTAT = RESU, NOM_CHAM = 'DEPL', GROUP_NO = 'A', INST = 1000.0}}
FIN()
