-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_missing_nodes\.lua:5: .*mail_missing_nodes\.mail:15: QUAD4 cell 'M2' needs 4 nodes, the section ends after 3
-- A QUAD4 cell with three nodes only.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
