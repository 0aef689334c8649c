-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_undefined_node\.lua:5: .*msh_undefined_node\.msh:14: element 2 refers to node 40, which is not defined \(expected a node of the \$Nodes section at line 4\)
-- A GMSH element on a node that $Nodes does not define.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
