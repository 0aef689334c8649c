-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_sans_group_no_absent\.lua:8: ZONE\[1\]/SANS_GROUP_NO: group 'COINS' not found in the mesh. did you mean 'COIN'\?
-- An excluded group the mesh does not have.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', SANS_GROUP_NO = 'COINS'}}
