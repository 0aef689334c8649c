-- expect-exit: 2
-- expect-output: <F> <POST_ELEM> .*axis_post_elem_norme\.lua:10: NORME: the model is axisymmetric \(MODELISATION='AXIS'\); aster-lite integrates the norms over the plane section only
-- POST_ELEM NORME integrates over the plane section, not per radian: an AXIS model is refused.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'AFFE', MAILLAGE = MA,
               AFFE = {TOUT = 'OUI', NOM_CMP = {'DX', 'DY'}, VALE = {0.0, 0.0}}}
N = POST_ELEM{NORME = {TYPE_NORM = 'L2', GROUP_MA = 'SURFACE', CHAM_GD = U, MODELE = MO}}
FIN{}
