-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_bad_nblige\.lua:5: .*mail_bad_nblige\.mail:5: NBLIGE= needs the number of lines of the section's header, got 'TROIS'
-- NBLIGE= (the number of header lines of a section) that is not a number.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
