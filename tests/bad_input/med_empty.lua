-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_empty\.lua:5: cannot open the MED file '.*med_empty\.med'
-- An empty MED file.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
FIN{}
