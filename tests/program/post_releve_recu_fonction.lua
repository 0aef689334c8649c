-- expect-exit: 0
-- expect-output: RELEVE: every check passed
-- POST_RELEVE_T (RESULTANTE and MOMENT, MOYENNE, EXTRACTION with LIST_INST) and
-- RECU_FONCTION on a result, against closed forms. The rectangle [0, 4] x [0, 1]
-- (four QUAD4, rectangle_4x1.mail), D_PLAN, E = 100, NU = 0.3: DX = 0 on the left
-- nodes, DY = 0 at N1, a traction SX = 2 on DROITE scaled by f(t) = t, MECA_STATIQUE at
-- t = 0.25, 0.5, 1. The exact solution is the uniform stress sigma_xx = SX t (sigma_yy
-- = sigma_xy = 0, sigma_zz = NU sigma_xx), u_x = (1 - NU^2) SX t / E x, u_y = -NU (1 +
-- NU) SX t / E y, which four QUAD4 reproduce exactly.
--  - The reactions at the left nodes balance the load: their resultant DX is -SX t
--    (the traction times DROITE's length), DY is 0, and their moment about (0, 0),
--    DRZ, balances the load's, -int_0^1 y SX t dy = -SX t / 2: DRZ = SX t / 2.
--  - DX along BAS (x from 0 to 4) is a x with a = (1 - NU^2) SX t / E: its mean
--    MOMENT_0 is 2 a, MOMENT_1 (the difference between the ends of the linear fit) 4 a.
--  - Along the bent path CHEMIN, (0,0) -> (1,0) -> (1,1) (abscissa s in [0, 2]), the
--    coordinates X = s then 1 and Y = 0 then s - 1: int X ds = 3/2, int X s ds = 11/6,
--    so MOMENT_0 = 3/4, MOMENT_1 = 12/4 (11/6 - 3/2) = 1, MOYE_INT = 1/4, MOYE_EXT =
--    5/4; int Y ds = 1/2, int Y s ds = 5/6: MOMENT_0 = 1/4, MOMENT_1 = 3 (5/6 - 1/2) = 1.
--  - RECU_FONCTION gives DX at P5 (x = 4) as the function 4 a(t) of INST, linear
--    between the instants: at t = 0.75 too; SIXX at a Gauss point of M2 is SX t (on
--    the instants 0.5 and 1, extended as a constant below 0.5: SX / 2 at t = 0.1).
local E, NU, SX = 100.0, 0.3, 2.0
local function a(t) return (1 - NU * NU) * SX * t / E end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'rectangle_4x1.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_NO = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = SX}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
L = DEFI_LIST_REEL{VALE = {0.25, 0.5, 1.0}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR, FONC_MULT = RAMPE}},
                  LIST_INST = L}

-- RESULTANTE and MOMENT of REAC_NODA, every instant (TOUT_ORDRE).
REAC = POST_RELEVE_T{ACTION = {OPERATION = 'EXTRACTION', INTITULE = 'REACTIONS', RESULTAT = R, NOM_CHAM = 'REAC_NODA',
                               TOUT_ORDRE = 'OUI', GROUP_NO = 'GAUCHE', RESULTANTE = {'DX', 'DY'},
                               MOMENT = 'DRZ', POINT = {0.0, 0.0}}}
for _, t in ipairs({0.25, 0.5, 1.0}) do
  local at = {NOM_PARA = 'INST', VALE = t}
  TEST_TABLE{TABLE = REAC, NOM_PARA = 'DX', FILTRE = at, VALE_CALC = -SX * t, REFERENCE = 'ANALYTIQUE',
             VALE_REFE = -SX * t, PRECISION = 1e-10}
  TEST_TABLE{TABLE = REAC, NOM_PARA = 'DY', FILTRE = at, VALE_CALC = 0.0, ORDRE_GRANDEUR = 1.0, REFERENCE = 'ANALYTIQUE',
             VALE_REFE = 0.0, CRITERE = 'ABSOLU', PRECISION = 1e-10}
  TEST_TABLE{TABLE = REAC, NOM_PARA = 'DRZ', FILTRE = at, VALE_CALC = SX * t / 2, REFERENCE = 'ANALYTIQUE',
             VALE_REFE = SX * t / 2, PRECISION = 1e-10}
end

-- MOYENNE of DX along BAS at the instants of a list.
L2 = DEFI_LIST_REEL{VALE = {0.5, 1.0}}
MOY = POST_RELEVE_T{ACTION = {OPERATION = 'MOYENNE', INTITULE = 'DX_BAS', RESULTAT = R, NOM_CHAM = 'DEPL',
                              LIST_INST = L2, GROUP_NO = 'BAS', NOM_CMP = 'DX'}}
for _, t in ipairs({0.5, 1.0}) do
  local function check(q, v)
    TEST_TABLE{TABLE = MOY, NOM_PARA = 'DX', FILTRE = {{NOM_PARA = 'INST', VALE = t}, {NOM_PARA = 'QUANTITE', VALE_K = q}},
               VALE_CALC = v, ORDRE_GRANDEUR = v == 0 and 1.0 or nil, REFERENCE = 'ANALYTIQUE', VALE_REFE = v,
               CRITERE = 'ABSOLU', PRECISION = 1e-12}
  end
  check('MOMENT_0', 2 * a(t))
  check('MOMENT_1', 4 * a(t))
  check('MINIMUM', 0.0)
  check('MAXIMUM', 4 * a(t))
  check('MOYE_INT', 0.0)
  check('MOYE_EXT', 4 * a(t))
end
if MOY:getNumberOfRows() ~= 12 then error("MOYENNE at 2 instants: " .. MOY:getNumberOfRows() .. " rows, expected 12") end

-- MOYENNE along a bent path, of the coordinates (a CHAM_GD).
GEOM = CREA_CHAMP{TYPE_CHAM = 'NOEU_GEOM_R', OPERATION = 'EXTR', MAILLAGE = MA, NOM_CHAM = 'GEOMETRIE'}
CHEM = POST_RELEVE_T{ACTION = {OPERATION = 'MOYENNE', INTITULE = 'CHEMIN', CHAM_GD = GEOM, GROUP_NO = 'CHEMIN',
                               NOM_CMP = {'X', 'Y'}}}
local expected = {X = {MOMENT_0 = 0.75, MOMENT_1 = 1.0, MINIMUM = 0.0, MAXIMUM = 1.0, MOYE_INT = 0.25, MOYE_EXT = 1.25},
                  Y = {MOMENT_0 = 0.25, MOMENT_1 = 1.0, MINIMUM = 0.0, MAXIMUM = 1.0, MOYE_INT = -0.25, MOYE_EXT = 0.75}}
for cmp, values in pairs(expected) do
  for q, v in pairs(values) do
    TEST_TABLE{TABLE = CHEM, NOM_PARA = cmp, FILTRE = {NOM_PARA = 'QUANTITE', VALE_K = q}, VALE_CALC = v,
               ORDRE_GRANDEUR = v == 0 and 1.0 or nil, REFERENCE = 'ANALYTIQUE', VALE_REFE = v, CRITERE = 'ABSOLU', PRECISION = 1e-14}
  end
end

-- EXTRACTION at the instants of a list.
EXT = POST_RELEVE_T{ACTION = {OPERATION = 'EXTRACTION', INTITULE = 'DX', RESULTAT = R, NOM_CHAM = 'DEPL',
                              LIST_INST = L2, GROUP_NO = 'P5', NOM_CMP = 'DX'}}
TEST_TABLE{TABLE = EXT, NOM_PARA = 'DX', FILTRE = {NOM_PARA = 'INST', VALE = 0.5}, VALE_CALC = 4 * a(0.5),
           REFERENCE = 'ANALYTIQUE', VALE_REFE = 4 * a(0.5), PRECISION = 1e-10}
if EXT:getNumberOfRows() ~= 2 then error('EXTRACTION with LIST_INST: not 2 rows') end

-- RECU_FONCTION: DX at P5 and SIXX at a Gauss point, functions of INST.
FDX = RECU_FONCTION{RESULTAT = R, NOM_CHAM = 'DEPL', NOM_CMP = 'DX', GROUP_NO = 'P5'}
for _, t in ipairs({0.25, 0.5, 0.75, 1.0}) do
  TEST_FONCTION{VALEUR = {FONCTION = FDX, VALE_PARA = t, VALE_CALC = 4 * a(t), REFERENCE = 'ANALYTIQUE',
                          VALE_REFE = 4 * a(t), PRECISION = 1e-10}}
end
FSIG = RECU_FONCTION{RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', NOM_CMP = 'SIXX', MAILLE = 'M2', POINT = 3,
                     LIST_INST = L2, PROL_GAUCHE = 'CONSTANT'}
TEST_FONCTION{VALEUR = {{FONCTION = FSIG, VALE_PARA = 1.0, VALE_CALC = SX, REFERENCE = 'ANALYTIQUE', VALE_REFE = SX,
                         PRECISION = 1e-10},
                        {FONCTION = FSIG, VALE_PARA = 0.1, VALE_CALC = SX * 0.5, REFERENCE = 'ANALYTIQUE',
                         VALE_REFE = SX * 0.5, PRECISION = 1e-10}}}
FDY = RECU_FONCTION{RESULTAT = R, NOM_CHAM = 'DEPL', NOM_CMP = 'DY', NOEUD = 'N10', INST = {0.5, 1.0}}
TEST_FONCTION{VALEUR = {FONCTION = FDY, VALE_PARA = 1.0, VALE_CALC = -NU * (1 + NU) * SX / E,
                        REFERENCE = 'ANALYTIQUE', VALE_REFE = -NU * (1 + NU) * SX / E, PRECISION = 1e-10}}
print('RELEVE: every check passed')
