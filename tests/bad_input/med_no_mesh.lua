-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_no_mesh\.lua:5: .*med_no_mesh\.med: the MED file holds no mesh \(expected at least one unstructured mesh\)
-- A MED (HDF5) file without any mesh (MEDfileOpen with MED_ACC_CREAT, then MEDfileClose).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
