-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_group_unknown_member\.lua:5: .*mail_group_unknown_member\.mail:31: cell 'M66' of group 'BAS' is not defined in the mesh
-- A group lists a cell that does not exist.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
