-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_version1\.lua:5: .*msh_version1\.msh:1: found '\$NOD' \(expected \$MeshFormat, the first line of a gmsh \.msh file, version 2\.2 or 4\.1\)
-- A GMSH file in the old MSH 1 format (no $MeshFormat).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
