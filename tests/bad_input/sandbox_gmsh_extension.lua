-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*sandbox_gmsh_extension\.lua:7: UNITE=19: .*sandbox_gmsh_extension\.py is not a \.msh file \(gmsh chooses by the extension how to open a file: a \.geo is a script, a \.py or \.exe a program; a mesh file handed to it must end in \.msh\); a sandboxed study does not hand it to gmsh \(aster-lite --unsafe-lua does\)
-- gmsh opens a file by its extension: a .py (a mesh inside) would be taken for
-- a program. A sandboxed study hands gmsh .msh files only.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = 'sandbox_gmsh_extension.py'}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
FIN{}
