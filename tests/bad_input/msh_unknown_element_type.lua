-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_unknown_element_type\.lua:5: .*msh_unknown_element_type\.msh:14: element 2 has gmsh type 93, which aster-lite does not read \(expected one of the gmsh types 15 \(POI1\), 1 \(SEG2\), 8 \(SEG3\), .* 5 \(HEXA8\), 17 \(HEXA20\), 12 \(HEXA27\)\)
-- A GMSH element of a type aster-lite does not know.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
