-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*sans_noeud_absent\.lua:8: DDL_IMPO\[1\]/SANS_NOEUD: node 'NN5' not found in the mesh; did you mean 'N5'
-- A node named in SANS_NOEUD that the mesh lacks is an error too, not a node left out of nothing.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', SANS_NOEUD = 'NN5', DX = 0.0, DY = 0.0}}
FIN{}
