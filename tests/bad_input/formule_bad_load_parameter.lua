-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA_F> .*formule_bad_load_parameter\.lua:12: FORCE_INTERNE\[1\]/FX: a load function may depend on X, Y, Z and INST only. its parameter 'TEMP' is none of them
-- A load function of a parameter other than X, Y, Z, INST.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
FX = FORMULE{VALE = '2 * TEMP', NOM_PARA = 'TEMP'}
F = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_INTERNE = {GROUP_MA = 'SURFACE', FX = FX}}
FIN{}
