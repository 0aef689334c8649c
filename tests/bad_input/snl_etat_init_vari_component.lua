-- expect-exit: 2
-- expect-output: <F> <STAT_NON_LINE> .*snl_etat_init_vari_component\.lua:14: ETAT_INIT/VARI: the field has the component V3, and the laws of the model have 2 internal variables \(V1 \.\.\. V2\)
-- ETAT_INIT's VARI must fit the laws: VMIS_ISOT_LINE has V1 and V2 only.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 100.0, SY = 1.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
V0 = CREA_CHAMP{TYPE_CHAM = 'ELGA_VARI_R', OPERATION = 'AFFE', MODELE = MO,
                AFFE = {GROUP_MA = 'SURFACE', NOM_CMP = {'V1', 'V3'}, VALE = {0.0, 0.0}}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE'}, ETAT_INIT = {VARI = V0}}
FIN{}
