-- expect-exit: 2
-- expect-output: <F> <CREA_MAILLAGE> .*crea_maillage_quad_tria3\.lua:7: MODI_MAILLE: OPTION='QUAD_TRIA3' is not available in aster-lite \(QUAD8_9 and TRIA6_7 are\)
-- MODI_MAILLE OPTION='QUAD_TRIA3' is code_aster's but not aster-lite's: refused by name.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
M2 = CREA_MAILLAGE{MAILLAGE = MA, MODI_MAILLE = {TOUT = 'OUI', OPTION = 'QUAD_TRIA3'}}
