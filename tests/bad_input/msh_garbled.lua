-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_garbled\.lua:5: .*msh_garbled\.msh: gmsh error: Error loading '.*msh_garbled\.msh'
-- A GMSH node line that is not numbers.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
