-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*lua_function_error\.lua:14: FORCE_INTERNE FX on cell M1 at X = 0\.1127016653792583, Y = 0\.1127016653792583, INST = 0: the study's Lua function failed: .*lua_function_error\.lua:12: 'undefined_variable' is not defined: it is neither a command of the catalogue nor a variable
-- A FORMULE given as a Lua function that fails when a load evaluates it.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
FX = FORMULE{VALE = function(x, y) return x + undefined_variable end, NOM_PARA = {'X', 'Y'}}
F = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_INTERNE = {GROUP_MA = 'SURFACE', FX = FX}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
