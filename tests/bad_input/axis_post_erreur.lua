-- expect-exit: 2
-- expect-output: <F> <POST_ERREUR> .*axis_post_erreur\.lua:11: MODELE is axisymmetric \(MODELISATION='AXIS'\); aster-lite integrates the errors over the plane section only
-- POST_ERREUR integrates over the plane section, not per radian: an AXIS model is refused.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.0, 0.0}}}
Z = FORMULE{VALE = '0*X', NOM_PARA = {'X', 'Y'}}
E = POST_ERREUR{OPTION = 'DEPL_ABSO', CHAM_GD = U, MODELE = MO, GROUP_MA = 'SURFACE', DX = Z, DY = Z}
FIN{}
