-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_empty\.lua:5: .*msh_empty\.msh: the gmsh file holds no mesh cell
-- An empty GMSH file.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
