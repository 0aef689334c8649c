-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*med_mesh_absent\.lua:5: .*med_mesh_absent\.med: no mesh called 'MB' in the MED file \(expected one of the meshes present: MA, MC\)
-- NOM_MED names a mesh the MED file lacks (it holds the empty meshes MA and MC).
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20, NOM_MED = 'MB'}
FIN{}
