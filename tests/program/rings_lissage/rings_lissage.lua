-- Two fitted concentric rings in contact (the set-up of code_aster's SSNP152):
-- C1 (R2 <= r <= R1) around C2 (R3 <= r <= R2), E and NU alike, plane stress,
-- GROT_GDEP, RELATION='ELAS'. The outer edge r = R1 and the inner edge r = R3
-- are given the radial displacements of the closed-form (Lame) solution of an
-- outer ring under an external pressure p pressing on the inner one: then the
-- contact pressure is uniform,
--   pc = 2 p R1^2 / ( R2^2 (1 - nu) + R1^2 (1 + nu)
--                     + (R1^2 - R2^2) / (R2^2 - R3^2) (R2^2 (1 - nu) + R3^2 (1 + nu)) ),
-- and in each ring u_r = ((1 - nu) a r + (1 + nu) b / r) / E with
--   C1: a = (pc R2^2 - p R1^2) / (R1^2 - R2^2), b = (pc - p) R1^2 R2^2 / (R1^2 - R2^2)
--   C2: a = -pc R2^2 / (R2^2 - R3^2),           b = -pc R2^2 R3^2 / (R2^2 - R3^2).
-- CONTINUE contact, LISSAGE='OUI', master r = R2 on C1, slave on C2: LAGS_C
-- must be -t pc at instant t (the displacements ramp with t). Meshes
-- (rings_lissage.geo, levels 1 and 2): QUAD4, 32 and 64 cells around, 4 and 8
-- across; level 3: level 1 in QUAD8 (SEG3 master and slave); the rings' nodes
-- on r = R2 at the same places. Contact integrated at Gauss points (the
-- default) on the three meshes, and at the nodes (INTEGRATION='AUTO') on
-- level 1: there the slave points sit on the master's vertices, and converge
-- only because the contact force is along the smoothed normal. Instants 0.1
-- and 1 (strains about 1e-4 and 1e-3: GROT_GDEP departs from the linear Lame
-- solution by about one strain). Checks: Newton converges within 4 iterations
-- at each instant (it takes 2); the relative L2 error of LAGS_C (POST_ERREUR
-- LAGR_RELA) below c dtheta^2 + 2 t pc / E (dtheta the angle of a cell, c =
-- 0.15 at Gauss points, 0.25 at the nodes), and falling more than three times
-- from level 1 to level 2 at t = 0.1 (second order).
-- Found (t = 0.1, t = 1): level 1 4.22e-3, 5.29e-3; level 2 1.18e-3, 2.26e-3;
-- level 3 2.88e-4, 1.27e-3; level 1 at the nodes 7.41e-3, 8.48e-3. (With
-- LISSAGE='NON', Gauss points: 2.61e-3, 3.68e-3 on level 1, 7.75e-4, 1.85e-3
-- on level 2: on fitted meshes the smoothed normals do not make the pressure
-- more accurate; at the nodes LISSAGE='NON' does not converge.)
DEBUT()
R1, R2, R3 = 1.0, 0.6, 0.2
E, NU, P = 1.0E9, 0.2, 1.0E6
PC = 2 * P * R1^2 / ((R2^2 * (1 - NU) + R1^2 * (1 + NU)) +
                     (R1^2 - R2^2) / (R2^2 - R3^2) * (R2^2 * (1 - NU) + R3^2 * (1 + NU)))
local a1, b1 = (PC * R2^2 - P * R1^2) / (R1^2 - R2^2), (PC - P) * R1^2 * R2^2 / (R1^2 - R2^2)
local a2, b2 = -PC * R2^2 / (R2^2 - R3^2), -PC * R2^2 * R3^2 / (R2^2 - R3^2)
UR1 = ((1 - NU) * a1 * R1 + (1 + NU) * b1 / R1) / E
UR3 = ((1 - NU) * a2 * R3 + (1 + NU) * b2 / R3) / E
print(string.format('RINGS: pc = %.10e, u_r(R1) = %.10e, u_r(R3) = %.10e', PC, UR1, UR3))
UX1 = FORMULE{VALE = 'UR1*X/R1', NOM_PARA = {'X', 'Y'}, UR1 = UR1, R1 = R1}
UY1 = FORMULE{VALE = 'UR1*Y/R1', NOM_PARA = {'X', 'Y'}, UR1 = UR1, R1 = R1}
UX3 = FORMULE{VALE = 'UR3*X/R3', NOM_PARA = {'X', 'Y'}, UR3 = UR3, R3 = R3}
UY3 = FORMULE{VALE = 'UR3*Y/R3', NOM_PARA = {'X', 'Y'}, UR3 = UR3, R3 = R3}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}}
LINST = DEFI_LIST_REEL{VALE = {0.0, 0.1, 1.0}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}

-- The cases: mesh level, contact integration, c of the tolerance.
local cases = {{1, 'GAUSS', 0.15}, {2, 'GAUSS', 0.15}, {3, 'GAUSS', 0.15}, {1, 'AUTO', 0.25}}
local errors = {}
for k, case in ipairs(cases) do
  local level, integration = case[1], case[2]
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = 'rings_lissage_' .. level .. '.msh'}
  local MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
  DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 19}
  MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = {
    {GROUP_MA = 'S1R1'}, {GROUP_MA = 'S1R2'}, {GROUP_MA = 'S2R2'}, {GROUP_MA = 'S2R3'}}}
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
  local RESU = STAT_NON_LINE{MODELE = MO,
    CHAM_MATER = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}},
    EXCIT = {{CHARGE = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {
                {GROUP_MA = 'S1R1', DX = UX1, DY = UY1}, {GROUP_MA = 'S2R3', DX = UX3, DY = UY3}}},
              FONC_MULT = RAMPE}},
    CONTACT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', LISSAGE = 'OUI',
                           ZONE = {GROUP_MA_MAIT = 'S1R2', GROUP_MA_ESCL = 'S2R2', CONTACT_INIT = 'OUI',
                                   INTEGRATION = integration}},
    COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, NEWTON = {REAC_ITER = 1}, CONVERGENCE = {ITER_GLOB_MAXI = 4}}
  errors[k] = {}
  for i, t in ipairs({0.1, 1.0}) do
    local U = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = RESU, NOM_CHAM = 'DEPL', INST = t}
    errors[k][i] = POST_ERREUR{OPTION = 'LAGR_RELA', CHAM_GD = U, MODELE = MO, GROUP_MA = 'S2R2',
      LAGS_C = FORMULE{VALE = '-T*PC', NOM_PARA = {'X', 'Y'}, PC = PC, T = t}}:get('ERREUR', 1)
    print(string.format('RINGS: level %d, %s, instant %.1f, relative L2 error of LAGS_C %.3e', level, integration, t,
                        errors[k][i]))
  end
end
-- Tolerance: c dtheta^2 for the mesh (dtheta = pi / 2 / nt; the relative
-- sag of a chord is dtheta^2 / 8) plus 2 t PC / E, twice the strain, for
-- GROT_GDEP against the linear solution.
for k, case in ipairs(cases) do
  local dtheta = math.pi / 2 / (8 * (case[1] == 2 and 2 or 1))
  for i, t in ipairs({0.1, 1.0}) do
    local tol = case[3] * dtheta^2 + 2 * t * PC / E
    if not (errors[k][i] < tol) then
      error(string.format('level %d, %s, instant %.1f: LAGS_C error %.3e above %.3e', case[1], case[2], t,
                          errors[k][i], tol))
    end
  end
end
local ratio = errors[1][1] / errors[2][1]
print(string.format('RINGS: error ratio level 1 / level 2 at instant 0.1 = %.2f', ratio))
if not (ratio > 3) then error(string.format('the LAGS_C error falls by %.2f only from level 1 to 2', ratio)) end
FIN()
