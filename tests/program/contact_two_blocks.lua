-- expect-exit: 0
-- Two deformable blocks that touch at the start, one pressed on the other,
-- on TRIA3, TRIA6, QUAD4 and QUAD8 (contact_two_blocks_*.mail), with DISCRETE
-- and CONTINUE contact: BLOC_HAUT's bottom ESCLAVE is the slave, BLOC_BAS's
-- top MAITRE the master; BAS holds DY = 0, GAUCHE (both blocks) DX = 0, and a
-- uniform traction (0, -P) acts on HAUT. Small strain, plane strain. Closed
-- form: the stress is uniform, SIYY = -P, SIXX = SIXY = 0, in both blocks;
-- the contact pressure is RN = -P at every slave node, the gap 0; the top
-- sinks by (1 - NU^2) P / E times the height 0.6. The elements reproduce this
-- linear displacement exactly (matching interface nodes), so it holds to
-- round-off. The meshes' interfaces differ by one unit in the last place
-- (0.3 and 3 x 0.1): every slave node had a gap of +5.6E-17 and none was in
-- contact at the first iteration ("0 active nodes"; then a singular matrix).
E, NU, P = 2.1E11, 0.3, 1.0E7
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
L = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 1}}
local nodes = {tria3 = 3, tria6 = 5, quad4 = 3, quad8 = 5}  -- slave nodes
for k, cell in ipairs({'tria3', 'tria6', 'quad4', 'quad8'}) do
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19 + k, FICHIER = 'contact_two_blocks_' .. cell .. '.mail'}
  local MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 19 + k}
  MA = MODI_MAILLAGE{reuse = MA, MAILLAGE = MA, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'ESCLAVE'}}}
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
  local CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  local LOAD = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}},
                              FORCE_CONTOUR = {GROUP_MA = 'HAUT', FY = -P}}
  for _, formulation in ipairs({'DISCRETE', 'CONTINUE'}) do
    local R = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = LOAD}},
      CONTACT = DEFI_CONTACT{MODELE = MO, FORMULATION = formulation,
                             ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'ESCLAVE'}},
      COMPORTEMENT = {RELATION = 'ELAS'}, INCREMENT = {LIST_INST = L}}
    local what = cell .. ' ' .. formulation
    local SIEF = CREA_CHAMP{TYPE_CHAM = 'ELGA_SIEF_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'SIEF_ELGA',
                            INST = 1.0}
    local function check(field, cmp, test, value, tolerance)
      local t = {NOM_CMP = cmp, TYPE_TEST = test, REFERENCE = 'ANALYTIQUE', VALE_REFE = value, LEGENDE = what}
      if value == 0 then
        t.VALE_CALC, t.CRITERE, t.TOLE_MACHINE, t.PRECISION = 0.0, 'ABSOLU', tolerance, tolerance
        t.ORDRE_GRANDEUR = 1.0  -- a zero VALE_CALC: the absolute tolerance's scale
      else
        t.VALE_CALC, t.PRECISION = value, 1.0E-9
      end
      if field == 'SIEF_ELGA' then
        t.CHAM_GD = SIEF
        TEST_RESU{CHAM_ELEM = t}
      else
        t.RESULTAT, t.INST, t.NOM_CHAM = R, 1.0, field
        TEST_RESU{RESU = t}
      end
    end
    check('SIEF_ELGA', 'SIYY', 'MIN', -P)
    check('SIEF_ELGA', 'SIYY', 'MAX', -P)
    check('SIEF_ELGA', 'SIXX', 'SOMM_ABS', 0.0, 1.0E-6 * P)
    check('SIEF_ELGA', 'SIXY', 'SOMM_ABS', 0.0, 1.0E-6 * P)
    check('DEPL', 'DY', 'MIN', -(1 - NU * NU) * P / E * 0.6)
    -- RN >= -P everywhere (0 off the slave) and its sum is -P per slave node: -P at each.
    check('CONT_NOEU', 'RN', 'MIN', -P)
    check('CONT_NOEU', 'RN', 'SOMM', -P * nodes[cell])
    check('CONT_NOEU', 'JEU', 'SOMM_ABS', 0.0, 1.0E-15)
  end
end
