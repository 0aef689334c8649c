-- The two-body contact patch test: BLOC_HAUT [0,1] x [0.5,1] pressed on
-- BLOC_BAS [0,1] x [0,0.5] (contact_patch.geo), two deformable blocks of the
-- same E and NU, plane strain, ELAS / PETIT. A uniform traction (0, -P) acts
-- on HAUT (y = 1); BAS (y = 0) holds DY = 0 and GAUCHE (x = 0, both blocks)
-- DX = 0: rollers, both blocks expand freely sideways. Closed form, in both
-- blocks: SIYY = -P, SIXX = SIXY = 0, so
--   u_x = NU (1 + NU) P / E x,   u_y = -(1 - NU^2) P / E y,
-- and the contact pressure is P all along the interface (RN = -P): the
-- interfaces' x displacements agree, nothing slides. The elements reproduce
-- this linear field exactly; a contact formulation passes the patch test when
-- the discrete solution is that field, to round-off.
-- Meshes (gmsh levels): 1..4 TRIA3, QUAD4, TRIA6, QUAD8 with 5 cells across
-- BLOC_BAS and 7 across BLOC_HAUT (non-matching: the interface nodes coincide
-- only at the ends); 5..8 the same cells with 5 and 5 (matching: the control,
-- where node-to-segment and Gauss-point contact are exact). Each mesh is run
-- with either side as the slave, with each formulation of FORMULATIONS.
-- Checks, every case: the global balance (the slave's contact forces RNY add
-- up to the load P x 1, the DY reactions on BAS as well: exact whatever the
-- formulation). Where the formulation is exact (matching meshes, or `exact`
-- in FORMULATIONS): RN = -P at every slave node and the displacements of the
-- closed form at every node, to 1e-8. Elsewhere the errors are printed, not
-- checked: DISCRETE and CONTINUE do not pass the patch test on non-matching
-- meshes (the master does not receive the consistent loads of a uniform
-- pressure: node-to-segment forces, Gauss points of the slave across master
-- kinks).
-- Found on the non-matching meshes, max |RN + P| / P over the slave nodes
-- (max |u - u_exact| / max |u| over all nodes), slave INTER_HAUT (7 cells) /
-- slave INTER_BAS (5 cells):
--   TRIA3 DISCRETE 9.2e-2 (2.0e-2) / 1.47e-1 (3.8e-2), CONTINUE 2.3e-3 (3.6e-4) / 7.2e-3 (4.1e-3)
--   QUAD4 DISCRETE 8.9e-2 (2.9e-2) / 1.48e-1 (5.5e-2), CONTINUE 2.4e-3 (4.5e-4) / 9.8e-3 (6.1e-3)
--   TRIA6 DISCRETE 5.3e-2 (6.5e-3) / 2.65e-1 (2.2e-2), CONTINUE 3.7e-2 (2.1e-3) / 4.7e-2 (1.1e-2)
--   QUAD8 DISCRETE 5.1e-2 (6.9e-3) / 2.46e-1 (2.3e-2), CONTINUE 3.8e-2 (2.2e-3) / 5.4e-2 (1.2e-2)
-- (on the matching meshes: below 3e-11 (2e-12) in every case).
-- CONTINUE with 6 Gauss points per slave cell (CONT_G6): TRIA3 4.6e-3 / 3.9e-3,
-- QUAD4 4.4e-3 / 4.2e-3, TRIA6 1.6e-2 / 2.4e-2, QUAD8 1.7e-2 / 2.0e-2: more
-- points reduce the error on quadratic cells, they do not remove it.
-- (CONTINUE with INTEGRATION = 'AUTO', at the slave nodes, gives DISCRETE's
-- numbers to the digits shown.)
DEBUT()
E, NU, P = 100.0, 0.3, 0.1  -- COEF_CONT's default, 100, is E: a well-scaled matrix
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
local EXX, EYY = NU * (1 + NU) * P / E, -(1 - NU * NU) * P / E  -- the closed form's strains

-- ===== The contact definitions: the one place to change. =====
-- name, DEFI_CONTACT's FORMULATION, keywords added to the ZONE, and whether
-- the formulation is exact on non-matching meshes (then checked to 1e-8).
FORMULATIONS = {
  {name = 'DISCRETE', formulation = 'DISCRETE', zone = {}, exact = false},
  {name = 'CONTINUE', formulation = 'CONTINUE', zone = {}, exact = false},
  {name = 'CONT_G6', formulation = 'CONTINUE', zone = {ORDRE_INT = 6}, exact = false},
  {name = 'LAC', formulation = 'CONTINUE', zone = {ALGO_CONT = 'LAC'}, exact = true},
  {name = 'LAC_PAIRE', formulation = 'CONTINUE', zone = {ALGO_CONT = 'LAC', ESPACE_LAGS_C = 'PAIRE'}, exact = true},
  {name = 'DEFI_CONT', command = 'DEFI_CONT', zone = {}, exact = true},  -- code_aster's newer spelling of LAC
}
local function contact(MO, f, master, slave)
  local zone = {GROUP_MA_MAIT = master, GROUP_MA_ESCL = slave}
  for k, v in pairs(f.zone) do zone[k] = v end
  if f.command == 'DEFI_CONT' then return DEFI_CONT{MODELE = MO, ZONE = zone} end
  return DEFI_CONTACT{MODELE = MO, FORMULATION = f.formulation, ZONE = zone}
end
-- =============================================================

local CELLS = {'TRIA3', 'QUAD4', 'TRIA6', 'QUAD8'}
local failures = {}
local function near(value, expected, tolerance, what)
  if not (math.abs(value - expected) <= tolerance) then
    failures[#failures + 1] = string.format('%s: %.10e, expected %.10e (tolerance %.1e)', what, value, expected,
                                            tolerance)
  end
end
-- The value of component cmp at node n of a nodal field (values node after node).
local function nodal(field)
  local cmps, values = field:getComponents(), field:getValues()
  local index = {}
  for i, c in ipairs(cmps) do index[c] = i end
  return function(n, cmp) return values[#cmps * (n - 1) + index[cmp]] end
end

for level = 1, 8 do
  local cell, matching = CELLS[(level - 1) % 4 + 1], level > 4
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = 'contact_patch_' .. level .. '.msh'}
  local MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
  DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 19}
  MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = {{GROUP_MA = 'INTER_BAS'}, {GROUP_MA = 'INTER_HAUT'}}}
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  local LOAD = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}},
                              FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -P}}
  local xyz = MA:getCoordinates()
  local allNodes = {}
  for n = 1, MA:getNumberOfNodes() do allNodes[n] = n end
  for _, sides in ipairs({{'INTER_BAS', 'INTER_HAUT'}, {'INTER_HAUT', 'INTER_BAS'}}) do
    local master, slave = sides[1], sides[2]
    local slaveNodes = MA:getNodes(slave)
    -- The slave's contact forces balance the load: up on BLOC_HAUT, down on BLOC_BAS.
    local slaveForce = slave == 'INTER_HAUT' and P or -P
    for _, f in ipairs(FORMULATIONS) do
      local what = string.format('%s %s slave %s %s', cell, matching and 'matching' or 'non-matching', slave, f.name)
      local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = LOAD}}, CONTACT = contact(MO, f, master, slave),
                              COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'}, INCREMENT = {LIST_INST = L},
                              CONVERGENCE = {RESI_GLOB_RELA = 1.0E-10}}
      local rn, u, reac = nodal(R:getField('CONT_NOEU', 1.0)), nodal(R:getField('DEPL', 1.0)),
                          nodal(R:getField('REAC_NODA', 1.0))
      local pressureError, sumRNY = 0.0, 0.0
      for _, n in ipairs(slaveNodes) do
        pressureError = math.max(pressureError, math.abs(rn(n, 'RN') + P) / P)
        sumRNY = sumRNY + rn(n, 'RNY')
      end
      local displacementError, uMax = 0.0, math.abs(EYY)  -- |u| is largest at y = 1: -EYY
      for _, n in ipairs(allNodes) do
        local x, y = xyz[3 * n - 2], xyz[3 * n - 1]
        displacementError = math.max(displacementError, math.abs(u(n, 'DX') - EXX * x) / uMax,
                                     math.abs(u(n, 'DY') - EYY * y) / uMax)
      end
      local sumReaction = 0.0
      for _, n in ipairs(MA:getNodes('BAS')) do sumReaction = sumReaction + reac(n, 'DY') end
      local iterations = R:getAccessParameters().ITER_GLOB
      print(string.format('PATCH: %-5s %-12s slave %-10s %-9s max|RN+P|/P = %.3e  max|u-u_exact|/|u|max = %.3e'
                          .. '  Newton iterations %d', cell, matching and 'matching' or 'non-matching', slave, f.name,
                          pressureError, displacementError, iterations[#iterations]))
      near(sumRNY, slaveForce, 1.0E-8 * P, what .. ': sum of RNY on the slave')
      near(sumReaction, P, 1.0E-8 * P, what .. ': sum of the DY reactions on BAS')
      if matching or f.exact then
        near(pressureError, 0.0, 1.0E-8, what .. ': max |RN + P| / P')
        near(displacementError, 0.0, 1.0E-8, what .. ': max |u - u_exact| / |u|max')
      end
    end
  end
end
if #failures > 0 then error('contact patch test:\n' .. table.concat(failures, '\n')) end
print('CONTACT_PATCH: every check passed')
FIN()
