-- expect-exit: 2
-- expect-output: <F> <CALC_CHAMP> .*calc_champ_vari_elas\.lua:13: VARI_INTERNE: the result has no internal variables \(VARI_ELGA\) at NUME_ORDRE 1 \(INST 0\): its behaviour \(ELAS\) has none
-- CALC_CHAMP of internal variables on a linear elastic result: ELAS has none.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0},
                    FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -1.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, VARI_INTERNE = 'VARI_NOEU'}
FIN{}
