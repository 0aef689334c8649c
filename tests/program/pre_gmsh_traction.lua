-- expect-exit: 0
-- expect-output: checks: 4 OK, 0 NOOK
-- PRE_GMSH -> LIRE_MAILLAGE -> MECA_STATIQUE: pre_gmsh_traction.msh (gmsh MSH 1) is the
-- 2 x 1 rectangle of two QUAD4 (physical 1), its left edge (physical 2), its right edge
-- (physical 3), a POI1 at the origin (physical 4) and one at the corner (2, 1) (physical 5);
-- node 99 belongs to no element and is dropped. PRE_GMSH names the groups GM1...GM5, and
-- a group of one POI1 is also a group of nodes (GM4, GM5).
-- C_PLAN, E = 1000, NU = 0.3, traction S = 10 on the right edge, DX = 0 on the left edge,
-- DY = 0 at the origin: uniaxial stress, u = (S X / E, -NU S Y / E), exact with QUAD4:
-- at (2, 1) DX = 2 S / E = 0.02, DY = -NU S / E = -0.003.
local E, NU, S = 1000.0, 0.3, 10.0
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = 'pre_gmsh_traction.msh'}
PRE_GMSH{UNITE_GMSH = 19, UNITE_MAILLAGE = 20}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {GROUP_MA = 'GM1', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GM2', DX = 0.0}, {GROUP_NO = 'GM4', DY = 0.0}},
                    FORCE_CONTOUR = {GROUP_MA = 'GM3', FX = S}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = CH}}
local function at(group, cmp, value)
  return {RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = group, NOM_CMP = cmp,
          VALE_CALC = value, REFERENCE = 'ANALYTIQUE', VALE_REFE = value, PRECISION = 1e-10}
end
TEST_RESU{RESU = {at('GM5', 'DX', 2 * S / E), at('GM5', 'DY', -NU * S / E),
                  at('GM4', 'DX', 0.0), at('GM4', 'DY', 0.0)}}

-- LIRE_MAILLAGE{FORMAT='GMSH'} reads the MSH 1 file itself as PRE_GMSH converts it.
MA2 = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
assert(MA2:getNumberOfNodes() == 6 and MA2:getNumberOfCells() == 6, 'LIRE_MAILLAGE GMSH: 6 nodes, 6 cells')
assert(table.concat(MA2:getGroupsOfCells(), ' ') == 'GM4 GM5 GM2 GM3 GM1', table.concat(MA2:getGroupsOfCells(), ' '))
assert(table.concat(MA2:getGroupsOfNodes(), ' ') == 'GM4 GM5', table.concat(MA2:getGroupsOfNodes(), ' '))
FIN{}
