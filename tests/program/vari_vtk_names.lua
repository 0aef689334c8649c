-- expect-exit: 0
-- expect-output: IMPR_RESU: FORMAT='VTK'
-- IMPR_RESU in VTK names the components of the VARI fields by the laws' names (NOM_VARI:
-- EPSPEQ, INDIPLAS for VMIS_ISOT_LINE); MED keeps V1, V2 as code_aster writes them. The
-- file is checked by the test program.vari_vtk_names_written (tests/program/CMakeLists.txt).
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 200000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 2000.0, SY = 200.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0},
                                             {GROUP_MA = 'HAUT', DY = 0.004}}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}, COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE'},
                  INCREMENT = {LIST_INST = L}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, VARI_INTERNE = {'VARI_NOEU'}}
IMPR_RESU{FORMAT = 'VTK', RESU = {RESULTAT = R, INST = 1.0}}
