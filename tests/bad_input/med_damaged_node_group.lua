-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_damaged_node_group\.lua:5: .*med_damaged_node_group\.med: TRIA3 cell 1 refers to node 1, the mesh has 0 nodes
-- A MED file (one TRIA3 in group SURF) with 64 zero bytes at offset 2320, in the metadata of its nodes: the library reads no node but still 3 names (was: SIGSEGV, 3 names written into a buffer for none).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
