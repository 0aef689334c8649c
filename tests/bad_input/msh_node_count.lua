-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_node_count\.lua:5: .*msh_node_count\.msh:10: found \$EndNodes after 4 node lines \(expected 5, as announced at line 5\)
-- A GMSH 2.2 $Nodes section announcing more nodes than it lists.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
