-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_unknown_element_type\.lua:5: .*msh_unknown_element_type\.msh: gmsh error: Error loading '.*msh_unknown_element_type\.msh'
-- A GMSH element of a type aster-lite does not know.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
