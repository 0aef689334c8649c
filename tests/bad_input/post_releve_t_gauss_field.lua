-- expect-exit: 2
-- expect-output: <F> <POST_RELEVE_T> .*post_releve_t_gauss_field\.lua:12: ACTION.*SIEF_ELGA is a field at Gauss points; POST_RELEVE_T reads fields at nodes \(CALC_CHAMP gives the ELNO and NOEU fields\)
-- POST_RELEVE_T on a field at Gauss points: refused, naming the fields it reads.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0, DY = 0.0}, {GROUP_MA = 'HAUT', DY = 0.01}}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}}
T = POST_RELEVE_T{ACTION = {OPERATION = 'EXTRACTION', INTITULE = 'S', RESULTAT = R, NOM_CHAM = 'SIEF_ELGA',
                            GROUP_NO = 'COIN', TOUT_CMP = 'OUI'}}
FIN{}
