-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_binary_garbage\.lua:5: .*msh_binary_garbage\.msh: byte 50 \(binary section \$Entities at byte 40\): the number of entities of dimension 0 is 749118580988207463, more than the 13 bytes left in the file can hold \(36 bytes or more each\): a damaged count or a truncated file
-- A binary GMSH 4.1 file whose header is right and whose $Entities are text: its first count, read as binary, is more than the file holds.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
