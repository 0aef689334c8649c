-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_undefined_node\.lua:5: .*msh_undefined_node\.msh: gmsh error: Wrong node index 40
-- A GMSH element on a node that $Nodes does not define.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
