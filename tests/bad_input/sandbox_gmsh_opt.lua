-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*sandbox_gmsh_opt\.lua:6: UNITE=20: .*sandbox_gmsh_opt\.msh is next to an option file, .*sandbox_gmsh_opt\.msh\.opt, which gmsh would run as a script; a sandboxed study does not hand it to gmsh \(aster-lite --unsafe-lua does\)
-- gmsh merges "<mesh>.opt" after the mesh, as a script (its SystemCall would
-- create sandbox_gmsh_opt_pwned): a sandboxed study refuses such a mesh.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
