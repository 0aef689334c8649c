-- expect-exit: 0
-- expect-output: CALC_CHAMP: EPSG_ELGA, EPSI_ELGA, EPSI_ELNO, EPSI_NOEU at 1 instant\(s\), on 4 cell\(s\).* OK   ANALYTIQUE .*CALC_CHAMP AXIS PATCH: every check passed
-- CALC_CHAMP's strains in AXIS, for every cell type (the distorted patches
-- patch_<type>.mail of [0, 2] x [0, 2], X the radius r, Y the axis z; nodes on the
-- axis included). The displacement u_r = A r, u_z = B z is imposed on the four sides
-- (AFFE_CHAR_MECA_F); it is the exact solution inside (a uniform strain with
-- eps_rr = eps_tt, so a uniform stress with s_rr = s_tt: ds_rr/dr + (s_rr - s_tt)/r = 0
-- without body force) and every cell type holds it. Its strains:
--   EPSI: EPXX = A, EPYY = B, EPZZ = u_r / r = A, EPXY = 0;
--   EPSG: EPXX = A + A^2/2, EPYY = B + B^2/2, EPZZ = ((1 + u_r/r)^2 - 1)/2 = A + A^2/2,
--         EPXY = 0,
-- at every Gauss point (code_aster's AXIS families: TRIA6 has 6), cell node and node,
-- checked to 1e-10 relative to |A| + |B|, and through TEST_RESU (POINT, NOEUD).
local E, NU, A, B = 200.0, 0.3, 2.0e-3, -1.0e-3

local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-10 * scale) then
    error(string.format('%s: %.17g, expected %.17g', what, a, b), 2)
  end
end

local eps = {EPXX = A, EPYY = B, EPZZ = A, EPXY = 0.0}
local epsg = {EPXX = A + A * A / 2, EPYY = B + B * B / 2, EPZZ = A + A * A / 2, EPXY = 0.0}
local scale = math.abs(A) + math.abs(B)

-- Every value of a field against the exact components; at least minValues values.
local function checkField(res, name, ref, what, minValues)
  local f = res:getField(name, 1.0)
  local cmp, v = f:getComponents(), f:getValues()
  if #v < minValues then error(what .. ': ' .. name .. ' has only ' .. #v .. ' values') end
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    near(v[i], ref[c], scale, what .. ': ' .. name .. ' ' .. c .. ' value ' .. i)
  end
end

local MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
local UR = FORMULE{VALE = 'A*X', NOM_PARA = 'X', A = A}
local UZ = FORMULE{VALE = 'B*Y', NOM_PARA = 'Y', B = B}
-- Cells, Gauss points per cell (code_aster's AXIS families), nodes per cell.
local layout = {TRIA3 = {8, 1, 3}, TRIA6 = {8, 6, 6}, QUAD4 = {4, 4, 4}, QUAD8 = {4, 9, 8}, QUAD9 = {4, 9, 9}}

for _, cell in ipairs({'TRIA3', 'TRIA6', 'QUAD4', 'QUAD8', 'QUAD9'}) do
  local cells, points, nodes = table.unpack(layout[cell])
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_' .. cell:lower() .. '.mail'}
  MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
  DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 20}
  MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
  CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
  BC = AFFE_CHAR_MECA_F{MODELE = MO, DDL_IMPO = {GROUP_MA = {'BAS', 'DROITE', 'HAUT', 'GAUCHE'}, DX = UR, DY = UZ}}
  R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {CHARGE = BC}, INST = 1.0}
  R = CALC_CHAMP{reuse = R, RESULTAT = R, DEFORMATION = {'EPSI_ELGA', 'EPSI_ELNO', 'EPSI_NOEU', 'EPSG_ELGA'}}
  local what = cell .. ' AXIS'
  checkField(R, 'EPSI_ELGA', eps, what, 4 * cells * points)
  checkField(R, 'EPSI_ELNO', eps, what, 4 * cells * nodes)
  checkField(R, 'EPSI_NOEU', eps, what, 4 * MA:getNumberOfNodes())
  checkField(R, 'EPSG_ELGA', epsg, what, 4 * cells * points)
  local function ref(v) return {VALE_CALC = v, REFERENCE = 'ANALYTIQUE', VALE_REFE = v, PRECISION = 1e-10} end
  local function occ(t, v)
    local o = ref(v)
    for key, value in pairs(t) do o[key] = value end
    o.RESULTAT, o.INST = R, 1.0
    return o
  end
  TEST_RESU{RESU = {
    occ({NOM_CHAM = 'EPSI_ELGA', MAILLE = 'M1', POINT = points, NOM_CMP = 'EPZZ'}, A),
    occ({NOM_CHAM = 'EPSI_ELGA', MAILLE = 'M1', POINT = 1, NOM_CMP = 'EPYY'}, B),
    occ({NOM_CHAM = 'EPSI_ELNO', GROUP_MA = 'CELL1', GROUP_NO = 'NC', NOM_CMP = 'EPZZ'}, A),
    occ({NOM_CHAM = 'EPSI_NOEU', GROUP_NO = 'NC', NOM_CMP = 'EPXX'}, A),
    occ({NOM_CHAM = 'EPSG_ELGA', MAILLE = 'M1', POINT = points, NOM_CMP = 'EPZZ'}, A + A * A / 2),
  }}
end
print('CALC_CHAMP AXIS PATCH: every check passed')
