-- expect-exit: 2
-- expect-output: <F> <CREA_MAILLAGE> .*crea_maillage_quad_line_linear\.lua:7: QUAD_LINE: no quadratic cell \(SEG3, TRIA6, TRIA7, QUAD8, QUAD9\) among the cells given
-- QUAD_LINE of a mesh that has no quadratic cell does nothing: refused.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
M2 = CREA_MAILLAGE{MAILLAGE = MA, QUAD_LINE = {TOUT = 'OUI'}}
