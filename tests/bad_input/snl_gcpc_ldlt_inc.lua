-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_gcpc_ldlt_inc\.lua:14: SOLVEUR: PRE_COND='LDLT_INC' \(code_aster's incomplete factorization\) is not available with METHODE='GCPC' in aster-lite
-- code_aster's GCPC preconditioner LDLT_INC (its default there): aster-lite has no incomplete
-- factorization, and the value is refused by name rather than replaced behind the user's back.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_MA = 'BAS', DY = 0.0}}}
F = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FX = 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = F}},
  SOLVEUR = {METHODE = 'GCPC', PRE_COND = 'LDLT_INC', NIVE_REMPLISSAGE = 1}, COMPORTEMENT = {RELATION = 'ELAS'},
  INCREMENT = {LIST_INST = L}}
FIN{}
