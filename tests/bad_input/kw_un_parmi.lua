-- expect-exit: 2
-- expect-output: <F> <AFFE_MODELE> .*kw_un_parmi\.lua:7: AFFE\[1\]: exactly one of TOUT, GROUP_MA, MAILLE is required, got TOUT, GROUP_MA \(rule UN_PARMI\('TOUT', 'GROUP_MA', 'MAILLE'\)\)
-- TOUT and GROUP_MA together (UN_PARMI).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', GROUP_MA = 'SURFACE', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
FIN{}
