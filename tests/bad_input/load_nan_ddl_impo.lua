-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*load_nan_ddl_impo\.lua:9: DDL_IMPO\[1\]: keyword DY = nan is not a finite number
-- NaN as an imposed displacement: refused by AFFE_CHAR_MECA, not found by the solver.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
local zero = 0.0
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = zero / zero}}
