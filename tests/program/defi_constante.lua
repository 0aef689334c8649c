-- expect-exit: 0
-- expect-output: DEFI_CONSTANTE: every check passed
-- DEFI_CONSTANTE: a function with the same value at any abscissa, of any parameter.
-- TEST_FONCTION and a call at arbitrary abscissas give VALE exactly; CALC_FONC_INTERP
-- tabulates it as VALE at each point. As FONC_MULT of a load (the set-up of
-- snl_force_nodale.lua: the unit square, one QUAD4, forces F at P2 and P3 giving the
-- uniform stress sigma_xx = 2 F) it scales the load by VALE at every instant:
--   u_x = (1 - NU^2) / E 2 F c x,   u_y = -NU (1 + NU) / E 2 F c y.
-- As the FX of AFFE_CHAR_MECA_F (a function of X, Y for the load) it is the force c.
local E, NU, F, c = 200.0, 0.3, 1.5, 0.4
local function near(x, y, tol, what)
  if not (math.abs(x - y) <= tol) then
    error(string.format('%s: %.17g, expected %.17g', what, x, y), 2)
  end
end

C = DEFI_CONSTANTE{VALE = c}
TEST_FONCTION{VALEUR = {
  {FONCTION = C, VALE_PARA = -1.0e3, VALE_CALC = c, REFERENCE = 'ANALYTIQUE', VALE_REFE = c,
   CRITERE = 'ABSOLU', PRECISION = 0.0},
  {FONCTION = C, VALE_PARA = 7.5, VALE_CALC = c, REFERENCE = 'ANALYTIQUE', VALE_REFE = c,
   CRITERE = 'ABSOLU', PRECISION = 0.0},
}}
near(C(0.0), c, 0.0, 'C(0)')
near(C(123.456), c, 0.0, 'C(123.456)')
LX = DEFI_LIST_REEL{VALE = {-2.0, 0.5, 3.0}}
T = CALC_FONC_INTERP{FONCTION = C, LIST_PARA = LX, NOM_PARA = 'INST'}
for _, x in ipairs({-2.0, 0.0, 1.25, 3.0}) do near(T(x), c, 1e-15, 'CALC_FONC_INTERP at ' .. x) end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 2}}
xyz = MA:getCoordinates()

for _, case in ipairs({
    {'FONC_MULT', AFFE_CHAR_MECA{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = F}}, C, F * c},
    {'AFFE_CHAR_MECA_F', AFFE_CHAR_MECA_F{MODELE = MO, FORCE_NODALE = {GROUP_NO = {'P2', 'P3'}, FX = C}}, nil, c}}) do
  local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM,
                          EXCIT = {{CHARGE = BC}, {CHARGE = case[2], FONC_MULT = case[3]}},
                          COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L}}
  for _, t in ipairs({0.5, 1.0}) do
    local s = 2 * case[4]
    local u = R:getField('DEPL', t):getValues()
    for n = 1, MA:getNumberOfNodes() do
      local what = string.format('%s at INST %g: node %d', case[1], t, n)
      near(u[2 * n - 1], (1 - NU * NU) / E * s * xyz[3 * n - 2], 1e-14, what .. ' DX')
      near(u[2 * n], -NU * (1 + NU) / E * s * xyz[3 * n - 1], 1e-14, what .. ' DY')
    end
  end
end
print('DEFI_CONSTANTE: every check passed')
