-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_empty\.lua:5: .*msh_empty\.msh: the file is empty \(expected a gmsh \.msh file, version 2\.2 or 4\.1, starting with \$MeshFormat\)
-- An empty GMSH file.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
