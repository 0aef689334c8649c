-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_truncated\.lua:5: .*mail_truncated\.mail:14: the file ends inside section QUAD4 opened at line 13 \(expected FINSF, truncated file\?\)
-- An ASTER mesh cut short inside a cell section.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
