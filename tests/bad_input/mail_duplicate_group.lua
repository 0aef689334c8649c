-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_duplicate_group\.lua:5: .*mail_duplicate_group\.mail:30: group 'HAUT' is defined twice \(first at line 27\)
-- A group defined twice.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
