-- The elastic-plastic benchmark (bench/run): a quarter of a thick cylinder
-- (a = 1, b = 2) under internal pressure, plane strain, QUAD8, von Mises
-- perfectly plastic (mesh: bench/thick_cylinder.py, bound to unit 20 on the
-- command line). The pressure rises to 0.9 of the limit pressure
-- p_L = 2 SY / sqrt(3) ln(b / a) in 20 increments; prints the radial
-- displacement of the inner point A at the end.
DEBUT()
MAIL = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                     AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
SY = 240.0
ACIER = DEFI_MATERIAU{ELAS = {E = 210000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 0.0, SY = SY}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
PLIM = 2 * SY / math.sqrt(3) * math.log(2)
CHAR = AFFE_CHAR_MECA{MODELE = MODELE,
                      DDL_IMPO = {{GROUP_NO = 'BAS', DY = 0.0}, {GROUP_NO = 'GAUCHE', DX = 0.0}},
                      PRES_REP = {GROUP_MA = 'INT', PRES = 0.9 * PLIM}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
TEMPS = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 20}}
RESU = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT,
                     EXCIT = {CHARGE = CHAR, FONC_MULT = RAMPE},
                     COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE'},
                     INCREMENT = {LIST_INST = TEMPS}}
IMPR_RESU{FORMAT = 'RESULTAT', RESU = {RESULTAT = RESU, NOM_CHAM = 'DEPL', GROUP_NO = 'A', INST = 1.0}}
FIN()
