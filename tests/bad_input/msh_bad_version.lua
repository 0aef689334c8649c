-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_bad_version\.lua:5: .*msh_bad_version\.msh: gmsh error: Unknown MSH file version 9\.1
-- A GMSH file of an unsupported format version.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
