-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_duplicate_cell\.lua:5: .*mail_duplicate_cell\.mail:19: duplicate cell name 'M3'
-- Two cells with the same name.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
