-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_v41_binary_long_chunk\.lua:5: .*msh_v41_binary_long_chunk\.msh: byte 40 \(binary section \$Entities at byte 40\): found '\$Entities(\\x00)+\.\.\.' \(expected a section marker '\$Name' alone on its line\)
-- A binary GMSH 4.1 file whose "$Entities" is followed by binary counts on the same 1023-byte chunk, without newline (found by fuzz_gmsh_mesh: gmsh reads the chunk as $Entities and allocates what the counts say).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
