-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_truncated\.lua:5: .*msh_truncated\.msh:4: section \$Nodes is not closed: the file ends at line 7 \(expected \$EndNodes; truncated file\?\)
-- A GMSH mesh cut short inside $Nodes.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
