-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_coef_cont_zero\.lua:8: ZONE\[1\]/COEF_CONT = 0: the coefficient must be > 0
-- COEF_CONT divides the multiplier equation: it must be positive.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', COEF_CONT = 0.0}}
