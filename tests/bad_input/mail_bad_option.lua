-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_bad_option\.lua:5: .*mail_bad_option\.mail:24: unknown option 'NAME' on a section line \(expected NOM= or INFO=\)
-- An unknown option on a section line.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
