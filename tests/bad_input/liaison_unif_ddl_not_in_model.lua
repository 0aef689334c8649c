-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*liaison_unif_ddl_not_in_model\.lua:10: LIAISON_UNIF\[1\]: keyword DDL \(value 2\) = 'DZ' is not allowed; allowed values: 'DX', 'DY'
-- DZ is no unknown of a plane model.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, LIAISON_UNIF = {GROUP_MA = 'HAUT', DDL = {'DX', 'DZ'}}}
FIN{}
