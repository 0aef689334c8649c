-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_not_hdf5\.lua:5: .*med_not_hdf5\.med: not a MED file \(no HDF5 signature\): expected a MED file written by Salome, code_aster or aster-lite
-- A text file where a MED (HDF5) file is expected.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
