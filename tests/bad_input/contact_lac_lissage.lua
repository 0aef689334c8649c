-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_lac_lissage\.lua:8: LISSAGE='OUI': ALGO_CONT='LAC' measures the gaps along the slave normals; give LISSAGE='NON'
-- LAC measures the gap along the slave cells' own normals: smoothed master normals (LISSAGE='OUI') are refused, not ignored.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', LISSAGE = 'OUI', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'LAC'}}
