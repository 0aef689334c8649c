-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*sandbox_gmsh_geo\.lua:7: UNITE=19: .*sandbox_gmsh_geo\.geo is a gmsh script \(\.geo\), whose commands gmsh runs \(SystemCall included\); a sandboxed study does not hand it to gmsh \(aster-lite --unsafe-lua does; or mesh it beforehand
-- A gmsh script runs shell commands (its SystemCall would create
-- sandbox_gmsh_geo_pwned): a sandboxed study never hands a .geo to gmsh.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = 'sandbox_gmsh_geo.geo'}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
FIN{}
