-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_garbled_number\.lua:5: .*mail_garbled_number\.mail:10: bad number '1,0' for coordinate 2 of node 'N5'
-- A coordinate that is not a number.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
