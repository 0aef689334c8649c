-- expect-exit: 2
-- expect-output: <F> <CALC_CHAMP> .*calc_champ_epsp_grot_gdep\.lua:14: EPSP_ELGA is the small-strain plastic strain \(EPSI less the elastic strain of SIEF_ELGA\), and the result was computed with DEFORMATION='GROT_GDEP': it is not available there
-- EPSP is refused on a large-strain result rather than computed with the wrong measure.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT1 = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 100.0, SY = 1.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT1}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}, {GROUP_MA = 'HAUT', DY = 1e-4}}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}, INCREMENT = {LIST_INST = L1},
                  COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', DEFORMATION = 'GROT_GDEP'}}
R = CALC_CHAMP{reuse = R, RESULTAT = R, DEFORMATION = {'EPSP_ELGA'}}
FIN{}
