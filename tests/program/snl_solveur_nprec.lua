-- expect-exit: 2
-- expect-output: SOLVEUR NPREC: every check passed.*<F> <LUA> the study went on after 4 fatal errors \(caught with pcall
-- The <F> the study catches with pcall still end the run with exit status 2.
-- SOLVEUR/NPREC and STOP_SINGULIER are honoured by every METHODE. The unit square
-- (one QUAD4), PETIT, D_PLAN, nearly incompressible (E = 1000, NU = 0.4999): DX = 0
-- on GAUCHE, DY = 0 at P1, a traction p = 1 on DROITE. Its stiffness loses about
-- three significant digits in the factorization: NPREC = 2 stops with a <F> that
-- says so; STOP_SINGULIER = 'NON' (only a zero pivot stops) and the default
-- NPREC = 8 give the exact solution, the uniform stress sigma_xx = p:
--   u_x = (1 - NU^2) p / E x,   u_y = -NU (1 + NU) p / E y.
local E, NU, p = 1000.0, 0.4999, 1.0
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad4.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = p}}
xyz = MA:getCoordinates()
local function solve(solveur)
  return pcall(STAT_NON_LINE, {MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR}},
                               SOLVEUR = solveur, INCREMENT = {LIST_INST = L}})
end
for _, m in ipairs({'UMFPACK', 'CHOLMOD', 'KLU', 'EIGEN_LU'}) do
  local ok, err = solve({METHODE = m, NPREC = 2})
  assert(not ok and err.aster_fatal:find(m .. ': the matrix is numerically singular: the pivot of column %d+ lost 3%.%d+ significant digits'),
         m .. ', NPREC = 2: ' .. (ok and 'no error' or err.aster_fatal))
  assert(err.aster_fatal:find('more than NPREC = 2', 1, true), err.aster_fatal)
  for _, solveur in ipairs({{METHODE = m, NPREC = 2, STOP_SINGULIER = 'NON'}, {METHODE = m}}) do
    local R
    ok, R = solve(solveur)
    assert(ok, m .. ': ' .. (ok and '' or R.aster_fatal))
    local u = R:getField('DEPL', 1.0):getValues()
    for n = 1, MA:getNumberOfNodes() do
      local ux, uy = (1 - NU * NU) * p / E * xyz[3 * n - 2], -NU * (1 + NU) * p / E * xyz[3 * n - 1]
      assert(math.abs(u[2 * n - 1] - ux) <= 1e-13 and math.abs(u[2 * n] - uy) <= 1e-13,
             string.format('%s, STOP_SINGULIER=%s: node %d has (%.17g, %.17g), expected (%.17g, %.17g)', m,
                           solveur.STOP_SINGULIER or 'OUI', n, u[2 * n - 1], u[2 * n], ux, uy))
    end
  end
end
print('SOLVEUR NPREC: every check passed')
