-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_v41_binary_parametric\.lua:5: .*msh_v41_binary_parametric\.msh: byte 1528 \(binary section \$Nodes at byte 945\): node block 9 has parametric flag 2 \(expected 0 or 1\)
-- A binary MSH 4.1 file with a node block whose parametric flag is 2 (was: SIGSEGV in gmsh).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
