-- expect-exit: 0
-- expect-output: solved
-- Run under prlimit --as: the study first fills the address space with Lua
-- strings, then frees 64 MB and solves a small problem. OpenBLAS maps its
-- 128 MB work buffer on its first call and retries forever when that fails: the
-- run hung. aster-lite maps it at start-up when the address space is limited.
local hog = {}
local filled = pcall(function()
  for i = 1, 1e10 do hog[i] = string.rep('x', 1e6) .. i end
end)
assert(not filled)
for _ = 1, 64 do hog[#hog] = nil end
collectgarbage()
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../bad_input/base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
print('solved')
