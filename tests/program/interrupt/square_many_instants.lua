-- Uniaxial plane strain of the unit square over 400 instants: long enough to be
-- stopped half-way by tests/program/interrupt/kill_test.sh. Bottom DY = 0, left
-- DX = 0, top DY = -0.01 INST, right free, small strain: the exact solution is
-- linear, DY = -0.01 INST Y and DX = 0.01 INST NU/(1-NU) X, and QUAD8 reproduce
-- it to round-off, so every instant on disk can be checked by hand.
MA0 = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}  -- ssnp150b.mail: one QUAD8
MA1 = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA0, GROUP_MA = 'SURFACE'}
MA2 = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA1, GROUP_MA = 'SURFACE'}
MA3 = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA2, GROUP_MA = 'SURFACE'}
MA4 = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA3, GROUP_MA = 'SURFACE'}
MAIL = MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA4, GROUP_MA = 'SURFACE'}

MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                     AFFE = {GROUP_MA = 'SURFACE', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
APPUIS = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {{GROUP_MA = 'BAS', DY = 0.0},
                                                      {GROUP_MA = 'GAUCHE', DX = 0.0}}}
TIRE = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {GROUP_MA = 'HAUT', DY = -0.01}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 400}}

RESU = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT,
                     EXCIT = {{CHARGE = APPUIS}, {CHARGE = TIRE, FONC_MULT = RAMPE}},
                     COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'},
                     INCREMENT = {LIST_INST = LINST}}
FIN{}
