-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_bad_version\.lua:5: .*msh_bad_version\.msh:2: MSH version 9\.1 is not supported \(expected 2\.2, 4\.0 or 4\.1\)
-- A GMSH file of an unsupported format version.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
