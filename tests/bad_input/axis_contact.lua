-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*axis_contact\.lua:8: the model is axisymmetric \(MODELISATION='AXIS'\), and aster-lite's contact terms are plane
-- aster-lite's contact is plane: DEFI_CONTACT refuses an axisymmetric model.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
CT = DEFI_CONTACT{MODELE = MO, ZONE = {GROUP_MA_MAIT = 'BAS', GROUP_MA_ESCL = 'HAUT'}}
FIN{}
