-- expect-exit: 2
-- expect-output: <F> <MECA_STATIQUE> .*meca_statique_no_cham_mater\.lua:9: keyword CHAM_MATER is mandatory and missing \(expected a cham_mater\)
-- MECA_STATIQUE without the materials.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}}
R = MECA_STATIQUE{MODELE = MO, EXCIT = {CHARGE = BC}}
FIN{}
