-- expect-exit: 2
-- expect-output: <F> <CREA_MAILLAGE> .*crea_maillage_lac_two_slaves\.lua:7: DECOUPE_LAC: slave cell M7 \(SEG2\): the 2D cell M1 under it also bears the slave cell M3; DECOUPE_LAC in aster-lite cuts a cell under one slave segment only
-- DECOUPE_LAC: the cell M1 bears two slave segments (M3 on top, M7 on the left); aster-lite cuts a cell under one only.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
M2 = CREA_MAILLAGE{MAILLAGE = MA, DECOUPE_LAC = {GROUP_MA_ESCL = {'HAUT', 'GAUCHE'}}}
