-- expect-exit: 0
-- expect-output: PLASTIC RESTART GROT_GDEP: every check passed
-- A restart of a von Mises law in large strain (VMIS_ISOT_LINE, DEFORMATION='GROT_GDEP'
-- and 'GDEF_LOG') continues exactly as the uninterrupted run, in D_PLAN and AXIS: one QUAD4, the unit
-- square (plastic_square.mail), BAS fixed, HAUT moved by DX = g(t), DY = e(t) (stretch
-- and shear: F has a rotation), g = 0.05, 0.1, 0.1 and e = 0.05, 0.1, 0.08 at INST 1, 2, 3
-- (the last step unloads). The element keeps the second Piola-Kirchhoff stress S while
-- SIEF_ELGA holds the Cauchy stress: ETAT_INIT converts it back, S = J F^-1 sigma F^-T.
-- Compared at INST 3 with the run that was not interrupted: DEPL, SIEF_ELGA, VARI_ELGA,
-- restarted from EVOL_NOLI at INST 2 and from the fields of INST 2 (DEPL, SIGM, VARI).
local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-9 * scale) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
local function same(a, b, name, t, what)
  local va, vb = a:getField(name, t):getValues(), b:getField(name, t):getValues()
  if #va ~= #vb then error(what .. ': ' .. name .. ' sizes differ') end
  local scale = 0.0
  for i = 1, #va do scale = math.max(scale, math.abs(va[i])) end
  for i = 1, #va do near(vb[i], va[i], scale, what .. ' ' .. name .. ' value ' .. i) end
end

DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'plastic_square.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MAT = DEFI_MATERIAU{ELAS = {E = 200000.0, NU = 0.3}, ECRO_LINE = {D_SIGM_EPSI = 2000.0, SY = 200.0}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
G = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 0.05, 2.0, 0.1, 3.0, 0.1}}
EY = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 0.05, 2.0, 0.1, 3.0, 0.08}}
L = DEFI_LIST_REEL{VALE = {0.0, 1.0, 2.0, 3.0}}
for _, case in ipairs({{'D_PLAN', 'GROT_GDEP'}, {'AXIS', 'GROT_GDEP'}, {'D_PLAN', 'GDEF_LOG'}, {'AXIS', 'GDEF_LOG'}}) do
  local modelisation, deformation = case[1], case[2]
  local MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = modelisation}}
  local BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0}}
  local UX = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DX = 1.0}}
  local UY = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'HAUT', DY = 1.0}}
  local function run(extra)
    local k = {MODELE = MO, CHAM_MATER = CM,
               EXCIT = {{CHARGE = BC}, {CHARGE = UX, FONC_MULT = G}, {CHARGE = UY, FONC_MULT = EY}},
               COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE', DEFORMATION = deformation}, INCREMENT = {LIST_INST = L},
               CONVERGENCE = {RESI_GLOB_RELA = 1e-12, ITER_GLOB_MAXI = 30}}
    for key, value in pairs(extra or {}) do k[key] = value end
    return STAT_NON_LINE(k)
  end
  local R = run()
  local p = R:getField('VARI_ELGA', 3.0):getValues()[1]
  if not (p > 0.01) then error(modelisation .. ': the run was meant to be plastic, p = ' .. p) end
  local RS = run({INCREMENT = {LIST_INST = L, INST_FIN = 2.0}})
  RS = run({reuse = RS, ETAT_INIT = {EVOL_NOLI = RS}})
  for _, name in ipairs({'DEPL', 'SIEF_ELGA', 'VARI_ELGA'}) do same(R, RS, name, 3.0, modelisation .. ' ' .. deformation .. ' EVOL_NOLI restart') end
  local U2 = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'DEPL', INST = 2.0}
  local S2 = CREA_CHAMP{TYPE_CHAM = 'ELGA_SIEF_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'SIEF_ELGA', INST = 2.0}
  local V2 = CREA_CHAMP{TYPE_CHAM = 'ELGA_VARI_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'VARI_ELGA', INST = 2.0}
  local RF = run({ETAT_INIT = {DEPL = U2, SIGM = S2, VARI = V2}, INCREMENT = {LIST_INST = L, INST_INIT = 2.0}})
  for _, name in ipairs({'DEPL', 'SIEF_ELGA', 'VARI_ELGA'}) do same(R, RF, name, 3.0, modelisation .. ' ' .. deformation .. ' field restart') end
end
print('PLASTIC RESTART GROT_GDEP: every check passed')
