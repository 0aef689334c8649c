-- expect-exit: 0
-- expect-output: MAILLE/NOEUD: every check passed
-- Cells and nodes designated by name (MAILLE, NOEUD) give what their groups give, and
-- the closed-form solution. The block [0, 2] x [0, 1] of 4 x 2 QUAD4 with interior nodes
-- moved (liaison_block.mail: M1..M8 the quads, M9..M12 BAS, M13 M14 DROITE, M15..M18 HAUT,
-- M19 M20 GAUCHE, whose nodes are N1, N6, N11),
-- D_PLAN, E = 1000, NU = 0.3: DY = 0 on the bottom edges, DX = 0 on the left ones, FORCE_CONTOUR
-- FY = Q on the top edges, PRES_REP P on the right edges. The stress is uniform,
-- sigma_xx = -P, sigma_yy = Q, sigma_xy = 0, and the displacement linear (exact on the
-- mesh): u_x = eps_xx x, u_y = eps_yy y with, in plane strain,
-- eps_xx = ((1 - NU^2) sigma_xx - NU (1 + NU) sigma_yy) / E and symmetrically for eps_yy.
-- Every keyword is given once by name and once by group: the two results agree to rounding.
local E, NU, Q, P = 1000.0, 0.3, 10.0, 4.0
local function near(a, b, tol, what)
  if not (math.abs(a - b) <= tol) then error(string.format('%s: %.17g, expected %.17g', what, a, b), 2) end
end
local QUADS = {'M1', 'M2', 'M3', 'M4', 'M5', 'M6', 'M7', 'M8'}
local BOTTOM, RIGHT, TOP = {'M9', 'M10', 'M11', 'M12'}, {'M13', 'M14'}, {'M15', 'M16', 'M17', 'M18'}

DEBUT{CODE = {NIV_PUB_WEB = 'INTERNET'}, DEBUG = {SDVERI = 'OUI'}, IGNORE_ALARM = {'MODELE1_63'}, PAR_LOT = 'NON'}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'liaison_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
L1 = DEFI_LIST_REEL{VALE = {0.0, 1.0}}

-- by = 'name' or 'group'
local function study(by)
  local named = by == 'name'
  local function cells(names, group) if named then return {MAILLE = names} else return {GROUP_MA = group} end end
  local function with(t, extra) for k, v in pairs(extra) do t[k] = v end return t end
  local all = {}
  for i = 1, 20 do all[i] = 'M' .. i end
  local mo = AFFE_MODELE{MAILLAGE = MA, AFFE = with(named and {MAILLE = all} or {TOUT = 'OUI'},
                                                   {PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'})}
  local cm = AFFE_MATERIAU{MAILLAGE = MA, AFFE = with(cells(QUADS, 'SURFACE'), {MATER = MAT})}
  local bc = AFFE_CHAR_MECA{MODELE = mo, INFO = 2,
    DDL_IMPO = {with(cells(BOTTOM, 'BAS'), {DY = 0.0}), with(named and {NOEUD = {'N1', 'N6', 'N11'}} or {GROUP_MA = 'GAUCHE'}, {DX = 0.0})}}
  local load = AFFE_CHAR_MECA{MODELE = mo, FORCE_CONTOUR = with(cells(TOP, 'HAUT'), {FY = Q}),
                              PRES_REP = with(cells(RIGHT, 'DROITE'), {PRES = P})}
  local rs = MECA_STATIQUE{MODELE = mo, CHAM_MATER = cm, EXCIT = {{CHARGE = bc}, {CHARGE = load}}, INST = 1.0,
                           TITRE = 'ignored'}
  -- Green-Lagrange on every cell, by name or TOUT: the same nonlinear solution.
  local rn = STAT_NON_LINE{MODELE = mo, CHAM_MATER = cm, EXCIT = {{CHARGE = bc}, {CHARGE = load}},
    COMPORTEMENT = with(named and {MAILLE = QUADS} or {TOUT = 'OUI'}, {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'}),
    INCREMENT = {LIST_INST = L1}, AFFICHAGE = {INFO_RESIDU = 'OUI'},
    SUIVI_DDL = {NOM_CHAM = 'DEPL', NOM_CMP = 'DY', NOEUD = 'N15'}}
  rs = CALC_CHAMP{reuse = rs, RESULTAT = rs, CONTRAINTE = 'SIGM_ELNO', MAILLE = named and {'M1', 'M2'} or nil,
                  GROUP_MA = (not named) and 'SURFACE' or nil}
  return rs, rn
end

local RS1, RN1 = study('name')
local RS2, RN2 = study('group')

local xyz = MA:getCoordinates()
local sxx, syy = -P, Q
local exx = ((1 - NU * NU) * sxx - NU * (1 + NU) * syy) / E
local eyy = ((1 - NU * NU) * syy - NU * (1 + NU) * sxx) / E
local u1, u2 = RS1:getField('DEPL', 1.0):getValues(), RS2:getField('DEPL', 1.0):getValues()
for n = 1, MA:getNumberOfNodes() do
  near(u1[2 * n - 1], exx * xyz[3 * n - 2], 1e-12, 'by name: DX of node ' .. n)
  near(u1[2 * n], eyy * xyz[3 * n - 1], 1e-12, 'by name: DY of node ' .. n)
  near(u1[2 * n - 1], u2[2 * n - 1], 1e-14, 'by name and by group: DX of node ' .. n)
  near(u1[2 * n], u2[2 * n], 1e-14, 'by name and by group: DY of node ' .. n)
end
local v1, v2 = RN1:getField('DEPL', 1.0):getValues(), RN2:getField('DEPL', 1.0):getValues()
local differs = false
for i = 1, #v1 do
  near(v1[i], v2[i], 1e-13, 'STAT_NON_LINE GROT_GDEP by MAILLE and by TOUT: value ' .. i)
  differs = differs or math.abs(v1[i] - u1[i]) > 1e-9
end
assert(differs, 'GROT_GDEP gives the small-strain solution: COMPORTEMENT by MAILLE was not applied')

-- SIGM_ELNO on M1 and M2 only (CALC_CHAMP MAILLE): the uniform stress there.
TAB = POST_RELEVE_T{ACTION = {OPERATION = 'EXTRACTION', INTITULE = 'S', RESULTAT = RS1, NOM_CHAM = 'SIGM_ELNO',
                              INST = 1.0, NOM_CMP = {'SIXX', 'SIYY'}, NOEUD = {'N1', 'N7'}, MAILLE = 'M1',
                              MOYE_NOEUD = 'NON', REPERE = 'GLOBAL'}}
local sixx, siyy = TAB:column('SIXX'), TAB:column('SIYY')
assert(#sixx == 2, 'two rows (N1 and N7 of M1), got ' .. #sixx)
for i = 1, 2 do
  near(sixx[i], sxx, 1e-10, 'SIXX row ' .. i)
  near(siyy[i], syy, 1e-10, 'SIYY row ' .. i)
end
IMPR_RESU{FORMAT = 'RESULTAT', RESU = {RESULTAT = RS1, NOM_CHAM = 'DEPL', MAILLE = 'M8', NOEUD = 'N1', IMPR_COOR = 'OUI'}}
print('MAILLE/NOEUD: every check passed')
FIN{FORMAT_HDF = 'NON', RETASSAGE = 'OUI', INFO_RESU = 'NON'}
