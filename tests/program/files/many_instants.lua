-- 80 instants of a linear elastic square (two QUAD4, unit 20): many small files
-- for the full-disk checks of outputs_test.sh; the study writes nothing but
-- STAT_NON_LINE's archive RESU.pvd.
MAIL = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MODELE = AFFE_MODELE{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = MAT}}
CHARGE = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {{GROUP_MA = 'BAS', DX = 0.0, DY = 0.0},
                                                      {GROUP_MA = 'HAUT', DY = 0.01}}}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 80}}
RESU = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {CHARGE = CHARGE},
                     INCREMENT = {LIST_INST = LINST}}
FIN{}
