-- expect-exit: 2
-- expect-output: <F> <CREA_MAILLAGE> .*crea_maillage_two_operations\.lua:7: exactly one of LINE_QUAD, QUAD_LINE, MODI_MAILLE, DECOUPE_LAC is required, got LINE_QUAD, DECOUPE_LAC \(rule UN_PARMI\('LINE_QUAD', 'QUAD_LINE', 'MODI_MAILLE', 'DECOUPE_LAC'\)\)
-- CREA_MAILLAGE does one operation at a time (UN_PARMI).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
M2 = CREA_MAILLAGE{MAILLAGE = MA, LINE_QUAD = {TOUT = 'OUI'}, DECOUPE_LAC = {GROUP_MA_ESCL = 'HAUT'}}
