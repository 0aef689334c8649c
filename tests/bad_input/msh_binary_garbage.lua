-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_binary_garbage\.lua:5: .*msh_binary_garbage\.msh: gmsh error: .* \(expected a gmsh \.msh file, version 2\.2 or 4\.1\)
-- A binary GMSH 4.1 file whose header is right and whose $Entities are not: gmsh's message, with what was expected.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
