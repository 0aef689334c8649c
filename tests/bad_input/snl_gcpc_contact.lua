-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_gcpc_contact\.lua:15: GCPC: the system holds Lagrange multipliers \(contact\): its matrix is symmetric but indefinite, and the conjugate gradient needs a symmetric positive definite one
-- GCPC is a conjugate gradient: contact's multipliers make the system indefinite, and it is
-- refused by name rather than left to diverge.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0}, FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -0.01}}
FIXE = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {GROUP_MA = {'MAITRE', 'MAITRE_BAS'}, DX = 0.0, DY = 0.0}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
CT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = CH}, {CHARGE = FIXE}}, CONTACT = CT,
                  COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}, SOLVEUR = {METHODE = 'GCPC'}}
