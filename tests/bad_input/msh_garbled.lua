-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_garbled\.lua:5: .*msh_garbled\.msh:8: found '3 1 one 0' \(expected a node line '<tag> <x> <y> <z>'\)
-- A GMSH node line that is not numbers.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
