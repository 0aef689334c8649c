-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_undefined_family\.lua:5: .*med_undefined_family\.med: cell M1 of mesh 'MA' is in family -1, which the MED file does not define \(a damaged file\?\)
-- A MED file whose family FAM_M_1 has number -5 (HDF5 attribute NUM) while its cell is in family -1 (was: read without the group SURF, exit 0).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
