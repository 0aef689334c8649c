-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_lac_mixed_zones\.lua:8: .*ZONE.*ALGO_CONT='STANDARD': ALGO_CONT='LAC' must be given in every zone or in none
-- LAC and the augmented Lagrangian are different terms: one DEFI_CONTACT takes one or the other.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', ZONE = {{GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'LAC'}, {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}}
