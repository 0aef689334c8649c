-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_reac_geom\.lua:8: keyword REAC_GEOM is not a keyword of DEFI_CONTACT
-- code_aster's geometric fixed point (REAC_GEOM...) is not available: the pairing is updated at every Newton iteration.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, REAC_GEOM = 'AUTOMATIQUE', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}
