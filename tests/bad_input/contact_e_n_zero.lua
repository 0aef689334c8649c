-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_e_n_zero\.lua:8: ZONE\[1\]/E_N = 0: the coefficient must be > 0
-- A zero penalty coefficient is no contact at all.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'PENALISATION', E_N = 0.0}}
