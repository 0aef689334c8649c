-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_undefined_node\.lua:5: .*mail_undefined_node\.mail:15: node 'N16' of cell 'M2' is not defined in any COOR section
-- A cell uses a node that no COOR section defines.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
