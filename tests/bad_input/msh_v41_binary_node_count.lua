-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_v41_binary_node_count\.lua:5: .*msh_v41_binary_node_count\.msh: byte 1812 \(binary section \$Nodes at byte 945\): node block 12 holds 5 nodes, more than the 23 announced at byte 960 \(the blocks before it hold 19\)
-- A binary MSH 4.1 file (ssnp150.geo, N = 2) whose $Nodes announces 23 nodes where its blocks hold 24 (was: double free in gmsh).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
