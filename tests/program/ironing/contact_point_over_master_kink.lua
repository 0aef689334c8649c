-- expect-exit: 0
-- expect-output: KINK: every check passed
-- A slave point right above a master kink (issue 23, found by ironing.lua).
-- An iron [-0.5, 0.5] x [1, 1.5] (E = 100, NU = 0.3, D_PLAN, ELAS / PETIT) is
-- pressed by DY = -0.05 on its top into a slab [-1, 1] x [0, 1] of two QUAD4
-- (bottom clamped), frictionless, the iron's bottom the slave, in one step.
-- The slab's top node N5 at x = 0 sinks most: its top is a groove there, and
-- the slave point above it sees two master segments. That point is
--   - CONTINUE's middle Gauss point (3 per cell, the default) when the iron's
--     bottom is one SEG2 [-0.5, 0.5] (kink_1.mail): above the groove, it
--     projects inside both segments, where the gap blends theirs
--     (contact/vertex_blend.hpp);
--   - DISCRETE's slave node N11 at x = 0 when it is two SEG2 (kink_2.mail):
--     held in the groove by both segments (contact_terms.cpp).
-- With one segment's gap alone both cycled in Newton's method with period 2
-- (the residual 2.7e-2 at every iteration from the 6th: the point's
-- projection jumped from one master segment to the other) and never
-- converged, even with the step cut 3 times. Now CONTINUE converges in 3
-- iterations, DISCRETE in 7. Checked: the problem being symmetric about
-- x = 0, the horizontal force on the iron is zero and the reactions of the two
-- bodies balance. The same with the iron's top moved by DX = 1e-3 (not
-- symmetric: the balances only), where the point no longer lies on the
-- bisector and its nearest segment alternates: CONTINUE holds it at the
-- vertex (5 iterations), DISCRETE by both segments (6); both cycled before.
DEBUT()
MAT = DEFI_MATERIAU{ELAS = {E = 100.0, NU = 0.3}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0}}
local failures = {}
for _, case in ipairs({{mesh = 'kink_1.mail', formulation = 'CONTINUE', dx = 0.0},
                       {mesh = 'kink_2.mail', formulation = 'DISCRETE', dx = 0.0},
                       {mesh = 'kink_1.mail', formulation = 'CONTINUE', dx = 1.0E-3},
                       {mesh = 'kink_2.mail', formulation = 'DISCRETE', dx = 1.0E-3}}) do
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = case.mesh}
  local MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
  DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 20}
  MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU_2D = {{GROUP_MA = 'DESSOUS_FER'}, {GROUP_MA = 'DESSUS'}}}
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  local BC = AFFE_CHAR_CINE{MODELE = MO, MECA_IMPO = {{GROUP_MA = 'BAS', DX = 0.0, DY = 0.0},
                                                      {GROUP_MA = 'HAUT_FER', DX = case.dx, DY = -0.05}}}
  local C = DEFI_CONTACT{MODELE = MO, FORMULATION = case.formulation,
                         ZONE = {GROUP_MA_MAIT = 'DESSUS', GROUP_MA_ESCL = 'DESSOUS_FER'}}
  local ok, R = pcall(STAT_NON_LINE, {MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}}, CONTACT = C,
                                      COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'PETIT'},
                                      INCREMENT = {LIST_INST = L}, CONVERGENCE = {RESI_GLOB_RELA = 1.0E-10}})
  if not ok then
    failures[#failures + 1] = case.formulation .. ' on ' .. case.mesh .. ', DX = ' .. case.dx .. ': ' .. tostring(R.aster_fatal or R)
  else
    local reac = R:getField('REAC_NODA', 1.0):getValues()
    local function resultant(group, c)
      local s = 0.0
      for _, n in ipairs(MA:getNodes(group)) do s = s + reac[2 * (n - 1) + c] end
      return s
    end
    local fx, fy = resultant('HAUT_FER', 1), resultant('HAUT_FER', 2)
    local tolerance = 1.0E-8 * math.abs(fy)
    if not ((case.dx ~= 0.0 or math.abs(fx) <= tolerance) and math.abs(fx + resultant('BAS', 1)) <= tolerance and
            math.abs(fy + resultant('BAS', 2)) <= tolerance) then
      failures[#failures + 1] = string.format('%s on %s, DX = %g: Fx = %.3e, Fy = %.3e: not symmetric or not balanced',
                                              case.formulation, case.mesh, case.dx, fx, fy)
    end
  end
end
if #failures > 0 then error('contact point over a master kink:\n' .. table.concat(failures, '\n')) end
print('KINK: every check passed')
FIN()
