-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_wrong_end\.lua:5: .*msh_wrong_end\.msh:10: found \$EndElements inside section \$Nodes opened at line 4 \(expected \$EndNodes\)
-- A GMSH section closed by the end marker of another one.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
