-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*contact_never_meet\.lua:14: UMFPACK: the matrix is numerically singular: .* the structure may be free to move \(missing Dirichlet conditions\?\) or the matrix is very ill conditioned \(unknown DX of node N3\) \(contact: 0 points in contact, 0 nodes, residual 0.00E\+00\). 1 instant\(s\) were stored before the failure
-- Contact surfaces that never meet: the master segment lies far to the side of the
-- slave edge, so nothing holds the body up: the message names the free motion.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'HAUT', DX = 0.0}, {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}},
  FORCE_INTERNE = {GROUP_MA = 'SURFACE', FY = -1.0}}
CT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}, CONTACT = CT,
  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
FIN{}
