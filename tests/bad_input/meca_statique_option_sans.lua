-- expect-exit: 2
-- expect-output: <F> <R:getField> .*meca_statique_option_sans\.lua:11: NOM_CHAM='SIEF_ELGA' is not stored in the result at INST=0 \(fields: DEPL, REAC_NODA, FORC_NODA\)
-- MECA_STATIQUE with OPTION = 'SANS' stores no stresses.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}, OPTION = 'SANS'}
S = R:getField('SIEF_ELGA', 0.0)
FIN{}
