-- expect-exit: 2
-- expect-output: <F> <CREA_MAILLAGE> .*crea_maillage_node_name_taken\.lua:7: LINE_QUAD: the new node name N1 is already a node's: choose another PREF_NOEUD or PREF_NUME
-- LINE_QUAD would name its first new node N1, which base.mail already has.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
M2 = CREA_MAILLAGE{MAILLAGE = MA, LINE_QUAD = {TOUT = 'OUI', PREF_NOEUD = 'N', PREF_NUME = 1}}
