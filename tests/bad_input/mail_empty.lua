-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_empty\.lua:5: .*mail_empty\.mail: the file is empty \(expected an ASTER mesh ended by FIN\)
-- An empty mesh file.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
