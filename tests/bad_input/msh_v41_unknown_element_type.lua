-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_v41_unknown_element_type\.lua:5: .*msh_v41_unknown_element_type\.msh:18: the elements of entity 1 \(dimension 2\) have gmsh type 93, which aster-lite does not read \(expected one of the gmsh types 15 \(POI1\), 1 \(SEG2\), .*\)
-- A GMSH 4.1 element block of a type aster-lite does not know.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
