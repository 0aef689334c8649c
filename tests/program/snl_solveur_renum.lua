-- expect-exit: 0
-- expect-output: linear solver UMFPACK, RENUM='AMD' \(ordering used: AMD\).*linear solver UMFPACK, RENUM='COLAMD' \(ordering used: COLAMD\).*linear solver UMFPACK, RENUM='METIS' \(ordering used: METIS\).*linear solver UMFPACK, RENUM='SANS' \(ordering used: natural\).*linear solver CHOLMOD, RENUM='AMD' \(ordering used: AMD\).*linear solver CHOLMOD, RENUM='METIS' \(ordering used: METIS\).*linear solver CHOLMOD, RENUM='SANS' \(ordering used: natural\).*linear solver KLU, RENUM='AMD' \(ordering used: AMD\).*linear solver KLU, RENUM='COLAMD' \(ordering used: COLAMD\).*linear solver KLU, RENUM='SANS' \(ordering used: natural\).*linear solver EIGEN_LU, RENUM='COLAMD' \(ordering used: COLAMD\).*linear solver MUMPS, RENUM='AMD' \(ordering used: AMD\).*linear solver MUMPS, RENUM='AMF' \(ordering used: AMF\).*linear solver MUMPS, RENUM='QAMD' \(ordering used: QAMD\).*linear solver MUMPS, RENUM='PORD' \(ordering used: AMD \(a dense matrix, which PORD cannot order\)\).*linear solver MUMPS, RENUM='SCOTCH' \(ordering used: SCOTCH\).*SOLVEUR: every check passed
-- SOLVEUR/RENUM is honoured by each METHODE for the orderings its catalogue block
-- allows (INFO = 2 prints the ordering the library reports having used), and every
-- ordering gives the exact solution; MECA_STATIQUE with MUMPS too (its RESI_RELA checked).
-- The one QUAD8's matrix is dense: MUMPS's PORD, which would end the process on it, is
-- replaced by AMD, and INFO = 2 says so. The unit square as one QUAD8, PETIT, D_PLAN,
-- E = 200, NU = 0.3, DX = 0 on GAUCHE, DY = 0 at P1, a traction p on DROITE: the
-- uniform stress sigma_xx = p, so u_x = (1 - NU^2) p / E x, u_y = -NU (1 + NU) p / E y.
local E, NU, p = 200.0, 0.3, 2.0
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'square_quad8.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {GROUP_NO = 'P1', DY = 0.0}}}
TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = p}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
xyz = MA:getCoordinates()
for _, case in ipairs({{'UMFPACK', 'AUTO'}, {'UMFPACK', 'AMD'}, {'UMFPACK', 'COLAMD'}, {'UMFPACK', 'METIS'},
                       {'UMFPACK', 'SANS'}, {'CHOLMOD', 'AUTO'}, {'CHOLMOD', 'AMD'}, {'CHOLMOD', 'METIS'},
                       {'CHOLMOD', 'SANS'}, {'KLU', 'AUTO'}, {'KLU', 'AMD'}, {'KLU', 'COLAMD'}, {'KLU', 'SANS'},
                       {'EIGEN_LU', 'AUTO'}, {'EIGEN_LU', 'COLAMD'}, {'MUMPS', 'AUTO'}, {'MUMPS', 'AMD'},
                       {'MUMPS', 'AMF'}, {'MUMPS', 'QAMD'}, {'MUMPS', 'PORD'}, {'MUMPS', 'SCOTCH'},
                       {'MUMPS', 'AUTO', 'MECA_STATIQUE'}}) do
  local u
  if case[3] == 'MECA_STATIQUE' then
    local R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR}},
                            SOLVEUR = {METHODE = case[1], RENUM = case[2], RESI_RELA = 1e-12}}
    u = R:getField('DEPL', 0.0):getValues()
  else
    local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR}},
                            SOLVEUR = {METHODE = case[1], RENUM = case[2]}, INFO = 2, INCREMENT = {LIST_INST = L}}
    u = R:getField('DEPL', 1.0):getValues()
  end
  for n = 1, MA:getNumberOfNodes() do
    local ux, uy = (1 - NU * NU) * p / E * xyz[3 * n - 2], -NU * (1 + NU) * p / E * xyz[3 * n - 1]
    if math.abs(u[2 * n - 1] - ux) > 1e-14 or math.abs(u[2 * n] - uy) > 1e-14 then
      error(string.format('%s, RENUM=%s: node %d has (%.17g, %.17g), expected (%.17g, %.17g)',
                          case[1], case[2], n, u[2 * n - 1], u[2 * n], ux, uy))
    end
  end
end
print('SOLVEUR: every check passed')
