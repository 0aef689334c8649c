-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_empty\.lua:5: .*med_empty\.med: not a MED file \(no HDF5 signature\): expected a MED file written by Salome, code_aster or aster-lite
-- An empty MED file.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
