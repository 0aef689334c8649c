-- expect-exit: 2
-- expect-output: <F> <CREA_MAILLAGE> .*crea_maillage_hexa\.lua:7: LINE_QUAD: cell M1 is a HEXA8; aster-lite converts 1D and 2D cells only \(SEG, TRIA, QUAD\)
-- LINE_QUAD of a HEXA8: code_aster makes a HEXA20, aster-lite refuses rather than leave it linear.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'crea_maillage_hexa.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
M2 = CREA_MAILLAGE{MAILLAGE = MA, LINE_QUAD = {TOUT = 'OUI'}}
