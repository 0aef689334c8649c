-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_duplicate_node\.lua:5: .*mail_duplicate_node\.mail:11: duplicate node name 'N5'
-- Two nodes with the same name.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
