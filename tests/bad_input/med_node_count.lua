-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_node_count\.lua:5: .*med_node_count\.med: the MED file announces 2147483647 nodes of mesh 'MA', more than its 10958 bytes can hold \(a damaged file; expected a MED file written by Salome, code_aster or aster-lite\)
-- A MED file whose coordinates announce 2^31 - 1 nodes (HDF5 attribute NBR) (was: internal error: std::bad_alloc).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
