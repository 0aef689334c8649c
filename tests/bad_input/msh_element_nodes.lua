-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_element_nodes\.lua:5: .*msh_element_nodes\.msh:14: element 2 \(gmsh type 3, QUAD4\) has 3 nodes after its 2 tags \(expected 4\)
-- A GMSH 2.2 QUAD4 element with 3 nodes.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
