-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*nul_in_group_name\.lua:8: DDL_IMPO\[1\]: keyword GROUP_MA = 'GAUCHE\\0DROITE' contains a NUL byte \('\\0'\)
-- A NUL byte in a group name (it imposed on GAUCHE alone, silently).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE\0DROITE', DX = 0.0, DY = 0.0}}
