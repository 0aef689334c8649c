-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_not_hdf5\.lua:5: cannot open the MED file '.*med_not_hdf5\.med'
-- A text file where a MED (HDF5) file is expected.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
