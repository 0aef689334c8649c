-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_same_cells\.lua:8: ZONE\[1\]: cell M5 is in both GROUP_MA_MAIT and GROUP_MA_ESCL
-- A surface in contact with itself.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, ZONE = {GROUP_MA_MAIT = 'BAS', GROUP_MA_ESCL = 'BAS'}}
