-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*liaison_ddl_node_absent\.lua:10: LIAISON_DDL\[1\]/NOEUD: node 'N99' not found in the mesh
-- A linear relation on a node the mesh does not have.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, LIAISON_DDL = {NOEUD = {'N1', 'N99'}, DDL = {'DX', 'DX'}, COEF_MULT = {1.0, -1.0},
                                                 COEF_IMPO = 0.0}}
FIN{}
