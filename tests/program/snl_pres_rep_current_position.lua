-- expect-exit: 0
-- expect-output: PRES_REP of XF: every check passed
-- A follower pressure that depends on the current position of the point
-- (code_aster's XF): the unit square (one QUAD4) translated rigidly by a along X
-- (DX = a, DY = 0 on every node, so no strain and no internal force), a pressure
-- p = c XF on its top edge, which now spans XF in [a, 1 + a]. The reactions
-- balance the pressure: their DY sum is int_a^(1+a) c x dx = c (1 + 2a) / 2,
-- their DX sum 0. Two-point Gauss is exact on this linear pressure.
local a, c = 0.5, 2.0
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 200.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
MOVE = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {TOUT = 'OUI', DX = a, DY = 0.0}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L2 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
PFORM = FORMULE{VALE = 'C*XF', C = c, NOM_PARA = 'XF'}
PTAB = DEFI_FONCTION{NOM_PARA = 'XF', VALE = {0.0, 0.0, 2.0, 2.0 * c}}
for _, p in ipairs({PFORM, PTAB}) do
  local P = AFFE_CHAR_MECA_F{MODELE = MO, PRES_REP = {GROUP_MA = 'HAUT', PRES = p}}
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM,
                          EXCIT = {{CHARGE = MOVE, FONC_MULT = RAMPE}, {CHARGE = P, TYPE_CHARGE = 'SUIV'}},
                          COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
                          INCREMENT = {LIST_INST = L2}}
  local T = POST_RELEVE_T{ACTION = {OPERATION = 'EXTRACTION', INTITULE = 'R', RESULTAT = R, NOM_CHAM = 'REAC_NODA',
                                    INST = 1.0, TOUT = 'OUI', RESULTANTE = {'DX', 'DY'}}}
  TEST_TABLE{TABLE = T, NOM_PARA = 'DY', VALE_CALC = c * (1 + 2 * a) / 2, VALE_REFE = c * (1 + 2 * a) / 2,
             REFERENCE = 'ANALYTIQUE', PRECISION = 1e-12}
  TEST_TABLE{TABLE = T, NOM_PARA = 'DX', VALE_CALC = 0.0, ORDRE_GRANDEUR = 1.0, VALE_REFE = 0.0, REFERENCE = 'ANALYTIQUE',
             CRITERE = 'ABSOLU', PRECISION = 1e-12}
end
print('PRES_REP of XF: every check passed')
