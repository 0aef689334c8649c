-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_no_fin\.lua:5: .*mail_no_fin\.mail:38: the file ends without FIN \(truncated file\?\)
-- An ASTER mesh whose last line (FIN) is missing.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
