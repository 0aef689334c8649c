-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_v41_binary_node_tag_64bit\.lua:5: .*msh_v41_binary_node_tag_64bit\.msh: byte 2165 \(binary section \$Elements at byte 2003\): element 3 refers to node 4294967305, which is not defined \(expected a node of a \$Nodes section before \$Elements, at byte 945\)
-- A binary MSH 4.1 file with an element on node 2^32 + 9, which does not exist (was: read as node 9, a wrong mesh).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
