-- expect-exit: 0
-- expect-output: written to .*/R\.pvd.*written to .*/R-2\.pvd.*written to .*/STAT_NON_LINE\.pvd
-- STAT_NON_LINE writes each converged instant to <output-dir>/<NAME>.pvd, NAME
-- being the variable the result is assigned to (also `local`); a second result
-- of the same name (a loop) gets NAME-2; a result that is not assigned to a
-- plain variable gets the command's name.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../bad_input/base.mail'}
MAIL = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MODELE = AFFE_MODELE{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = MAT}}
CHARGE = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {{GROUP_MA = 'BAS', DX = 0.0, DY = 0.0},
                                                      {GROUP_MA = 'HAUT', DY = 0.01}}}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
local function solve()
  return STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {CHARGE = CHARGE},
                       INCREMENT = {LIST_INST = LINST}}
end
for i = 1, 2 do
  local R = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {CHARGE = CHARGE},
                          INCREMENT = {LIST_INST = LINST}}
end
local T = {solve()}
FIN{}
