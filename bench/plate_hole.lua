-- The linear-static benchmark (bench/run): a quarter of a square plate with a
-- hole under remote tension, plane stress, QUAD8 (mesh: bench/plate_hole.py,
-- bound to unit 20 on the command line). MECA_STATIQUE, then the nodal stress
-- SIGM_NOEU by CALC_CHAMP; prints SIXX at the top of the hole (A), which tends
-- to about 3.02 times the remote stress (3 for an infinite plate).
DEBUT()
MAIL = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                     AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = MAT}}
CHAR = AFFE_CHAR_MECA{MODELE = MODELE,
                      DDL_IMPO = {{GROUP_NO = 'BAS', DY = 0.0}, {GROUP_NO = 'GAUCHE', DX = 0.0}},
                      FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = 1.0}}
RESU = MECA_STATIQUE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {CHARGE = CHAR}}
RESU = CALC_CHAMP{reuse = RESU, RESULTAT = RESU, CONTRAINTE = 'SIGM_NOEU'}
IMPR_RESU{FORMAT = 'RESULTAT', RESU = {RESULTAT = RESU, NOM_CHAM = {'DEPL', 'SIGM_NOEU'}, GROUP_NO = 'A'}}
FIN()
