-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*pre_gmsh_undefined_node\.lua:5: .*pre_gmsh_undefined_node\.msh:9: node 4 of element 1 is not defined in the nodes section
-- LIRE_MAILLAGE{FORMAT='GMSH'} on a MSH 1 file whose triangle uses a node it does not define.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
FIN{}
