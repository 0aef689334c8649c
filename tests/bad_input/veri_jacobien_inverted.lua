-- expect-exit: 2
-- expect-output: <F> <AFFE_MODELE> .*veri_jacobien_inverted\.lua:8: VERI_JACOBIEN: 1 cell is inverted \(Jacobian < 0 at every Gauss point: nodes numbered clockwise\): M2 \(QUAD4 of SURFACE\); 1 cell is too distorted \(the Jacobian changes sign between Gauss points\): M1 \(QUAD4 of SURFACE\)\. The elements need a positive Jacobian
-- VERI_JACOBIEN (on by default) names the cells the elements cannot integrate,
-- at AFFE_MODELE: before, the first computation stopped on the first of them
-- without naming it.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = 'COIN', FX = 1.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L}}
FIN{}
