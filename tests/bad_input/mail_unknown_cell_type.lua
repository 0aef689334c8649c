-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*mail_unknown_cell_type\.lua:5: .*mail_unknown_cell_type\.mail:13: unknown section or cell type 'QUAD5'. did you mean QUAD4, QUAD8 or QUAD9\? \(expected TITRE, COOR_1D, COOR_2D, COOR_3D, a cell type such as QUAD8, GROUP_MA, GROUP_NO or FIN\)
-- A cell section of an unknown type.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
