-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*comportement_maille_absent\.lua:12: COMPORTEMENT\[1\]/MAILLE: cell 'M0' not found in the mesh; did you mean
-- COMPORTEMENT by cell name: a name the mesh lacks stops the analysis before it starts.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP', MAILLE = 'M0'}}
FIN{}
