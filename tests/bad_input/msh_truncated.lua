-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_truncated\.lua:5: .*msh_truncated\.msh: gmsh error: Error loading '.*msh_truncated\.msh'
-- A GMSH mesh cut short inside $Nodes.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
