-- expect-exit: 2
-- expect-output: <F> <DEFI_CONT> .*defi_cont_nitsche\.lua:8: ZONE.1.: keyword ALGO_CONT = .NITSCHE. is not allowed. allowed values: .LAGRANGIEN.
-- DEFI_CONT's Nitsche method is not in aster-lite: refused by name, never replaced by another method.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONT{MODELE = MO, ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', ALGO_CONT = 'NITSCHE'}}
