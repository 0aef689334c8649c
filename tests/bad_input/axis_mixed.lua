-- expect-exit: 2
-- expect-output: <F> <AFFE_MODELE> .*axis_mixed\.lua:7: MODELISATION='AXIS' is assigned to some cells and D_PLAN or C_PLAN to others
-- An axisymmetric model has AXIS on every cell (its loads are per radian).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {{TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'},
                                        {MAILLE = 'M2', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}}
FIN{}
