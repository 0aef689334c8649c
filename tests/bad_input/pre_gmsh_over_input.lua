-- expect-exit: 2
-- expect-output: <F> <PRE_GMSH> .*pre_gmsh_over_input\.lua:6: UNITE=20 is bound to .*base\.mail, an input of the study \(bound for reading by DEFI_FICHIER at .*\): aster-lite never writes over a file the study read
-- PRE_GMSH asked to write its ASTER mesh over a file the study declared for reading.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail', ACCES = 'OLD'}
PRE_GMSH{UNITE_GMSH = 19, UNITE_MAILLAGE = 20}
FIN{}
