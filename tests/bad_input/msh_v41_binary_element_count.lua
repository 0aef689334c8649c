-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_v41_binary_element_count\.lua:5: .*msh_v41_binary_element_count\.msh: byte 2433 \(binary section \$Elements at byte 2003\): element block 6 holds 4 elements, more than the 12 announced at byte 2021 \(the blocks before it hold 9\)
-- A binary MSH 4.1 file whose $Elements announces 12 elements where its blocks hold 13 (was: double free in gmsh).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
