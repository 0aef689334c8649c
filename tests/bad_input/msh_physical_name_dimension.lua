-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh_physical_name_dimension\.lua:5: .*msh_physical_name_dimension\.msh:6: physical name ..X.. has dimension 9 \(expected 0, 1, 2 or 3\)
-- An ASCII MSH 4.1 file with a physical name of dimension 9 (was: SIGSEGV in gmsh, which indexes a table by the dimension).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
