-- expect-exit: 0
-- expect-output: CALC_CHAMP: EPSG_ELGA, EPSI_ELGA, EPSI_ELNO, EPSI_NOEU, REAC_NODA, SIEF_ELNO, SIEF_NOEU, SIEQ_ELGA, SIEQ_ELNO, SIEQ_NOEU, SIGM_ELGA, SIGM_ELNO, SIGM_NOEU at 2 instant\(s\), on 4 cell\(s\).* OK   ANALYTIQUE .*CALC_CHAMP PATCH: every check passed
-- CALC_CHAMP's patch test, for every cell type (TRIA3, TRIA6, QUAD4, QUAD8, QUAD9: the
-- distorted patches patch_<type>.mail of [0, 2] x [0, 2]) in D_PLAN and C_PLAN. E = 200,
-- NU = 0.3; P1 = (0, 0) is fixed, P2 = (2, 0) has DY = 0, and the four sides carry the
-- tractions of the uniform stress SXX = 3, SYY = -1.25, SXY = 0.8 (FORCE_CONTOUR, scaled by
-- FONC_MULT f(t) = t at the instants 0.5 and 1). The exact solution is that stress
-- everywhere, with SIZZ = NU (SXX + SYY) in plane strain and 0 in plane stress, and the
-- uniform strain of Hooke's law:
--   D_PLAN: EPXX = ((1 - NU^2) SXX - NU (1 + NU) SYY) / E, EPYY likewise, EPZZ = 0;
--   C_PLAN: EPXX = (SXX - NU SYY) / E, EPYY likewise, EPZZ = -NU (SXX + SYY) / E;
--   EPXY = (1 + NU) SXY / E (tensor shear).
-- The displacement is u = H x with H = [[EPXX, 2 EPXY], [0, EPYY]] (uy(P2) = 0 fixes the
-- rotation), so the Green-Lagrange strain is EPSG = eps + H^T H / 2. Every value of every
-- field, at every Gauss point, cell node and node, is checked against these (1e-10 relative
-- to the largest stress or strain), and SIEQ against principal stresses computed here from
-- the in-plane Mohr circle (centre c, radius r): PRIN = sort(c - r, c + r, SIZZ), VMIS from
-- the principal differences, TRESCA = max - min, TRSIG, TRIAX, VMIS_SG.
-- TEST_RESU reads SIGM_ELNO, SIGM_NOEU, EPSI_ELGA, SIEQ_ELNO (MAILLE / GROUP_MA + POINT,
-- NOEUD / GROUP_NO) and CREA_CHAMP extracts ELNO and ELGA fields.
local E, NU = 200.0, 0.3
local S = {SIXX = 3.0, SIYY = -1.25, SIXY = 0.8}

local function near(a, b, scale, what)
  if not (math.abs(a - b) <= 1e-10 * scale) then
    error(string.format('%s: %.17g, expected %.17g', what, a, b), 2)
  end
end

-- The exact fields at instant t for a modelisation.
local function exact(modelisation, t)
  local sxx, syy, sxy = S.SIXX * t, S.SIYY * t, S.SIXY * t
  local szz = modelisation == 'D_PLAN' and NU * (sxx + syy) or 0.0
  local exx, eyy, ezz
  if modelisation == 'D_PLAN' then
    exx = ((1 - NU * NU) * sxx - NU * (1 + NU) * syy) / E
    eyy = ((1 - NU * NU) * syy - NU * (1 + NU) * sxx) / E
    ezz = 0.0
  else
    exx = (sxx - NU * syy) / E
    eyy = (syy - NU * sxx) / E
    ezz = -NU * (sxx + syy) / E
  end
  local exy = (1 + NU) * sxy / E
  local sig = {SIXX = sxx, SIYY = syy, SIZZ = szz, SIXY = sxy}
  local eps = {EPXX = exx, EPYY = eyy, EPZZ = ezz, EPXY = exy}
  -- H = [[exx, 2 exy], [0, eyy]]: (H^T H) = [[exx^2, 2 exx exy], [., 4 exy^2 + eyy^2]].
  local epsg = {EPXX = exx + 0.5 * exx * exx, EPYY = eyy + 0.5 * (4 * exy * exy + eyy * eyy),
                EPZZ = modelisation == 'D_PLAN' and 0.0 or -NU / (1 - NU) * (exx + eyy
                       + 0.5 * exx * exx + 0.5 * (4 * exy * exy + eyy * eyy)),
                EPXY = exy + exx * exy}
  local c, r = 0.5 * (sxx + syy), math.sqrt((0.5 * (sxx - syy)) ^ 2 + sxy ^ 2)
  local p = {c - r, c + r, szz}
  table.sort(p)
  local vmis = math.sqrt(0.5 * ((p[1] - p[2]) ^ 2 + (p[2] - p[3]) ^ 2 + (p[3] - p[1]) ^ 2))
  local tr = sxx + syy + szz
  local sieq = {VMIS = vmis, TRESCA = p[3] - p[1], PRIN_1 = p[1], PRIN_2 = p[2], PRIN_3 = p[3],
                VMIS_SG = tr >= 0 and vmis or -vmis, TRSIG = tr, TRIAX = tr / 3 / vmis}
  return sig, eps, epsg, sieq
end

-- Every value of a field against the exact components (those listed in `ref`).
local function checkField(res, name, t, ref, scale, what, minValues)
  local f = res:getField(name, t)
  local cmp, v = f:getComponents(), f:getValues()
  if #v < minValues then error(what .. ': ' .. name .. ' has only ' .. #v .. ' values') end
  local checked = 0
  for i = 1, #v do
    local c = cmp[(i - 1) % #cmp + 1]
    if ref[c] ~= nil then
      near(v[i], ref[c], scale, what .. ': ' .. name .. ' ' .. c .. ' value ' .. i)
      checked = checked + 1
    end
  end
  if checked == 0 then error(what .. ': ' .. name .. ': no component checked') end
end

local RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
local L = DEFI_LIST_REEL{VALE = {0.5, 1.0}}
local MAT = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
-- Points per cell of the model's rule (code_aster's FPG1, FPG3, FPG4, FPG9), nodes per cell.
local layout = {TRIA3 = {8, 1, 3}, TRIA6 = {8, 3, 6}, QUAD4 = {4, 4, 4}, QUAD8 = {4, 9, 8}, QUAD9 = {4, 9, 9}}

for _, cell in ipairs({'TRIA3', 'TRIA6', 'QUAD4', 'QUAD8', 'QUAD9'}) do
  for _, modelisation in ipairs({'D_PLAN', 'C_PLAN'}) do
    local what = cell .. ' ' .. modelisation
    local cells, points, nodes = table.unpack(layout[cell])
    DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'patch_' .. cell:lower() .. '.mail'}
    MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
    DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 20}
    MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = modelisation}}
    CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
    BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_NO = 'P1', DX = 0.0, DY = 0.0}, {GROUP_NO = 'P2', DY = 0.0}}}
    TR = AFFE_CHAR_MECA{MODELE = MO, FORCE_CONTOUR = {
      {GROUP_MA = 'DROITE', FX = S.SIXX, FY = S.SIXY}, {GROUP_MA = 'HAUT', FX = S.SIXY, FY = S.SIYY},
      {GROUP_MA = 'GAUCHE', FX = -S.SIXX, FY = -S.SIXY}, {GROUP_MA = 'BAS', FX = -S.SIXY, FY = -S.SIYY}}}
    -- QUAD4 in C_PLAN without stresses: CALC_CHAMP computes SIEF_ELGA from DEPL.
    local option = (cell == 'QUAD4' and modelisation == 'C_PLAN') and 'SANS' or 'SIEF_ELGA'
    R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = TR, FONC_MULT = RAMPE}},
                      LIST_INST = L, OPTION = option}
    R = CALC_CHAMP{reuse = R, RESULTAT = R,
                   CONTRAINTE = {'SIEF_ELNO', 'SIEF_NOEU', 'SIGM_ELGA', 'SIGM_ELNO', 'SIGM_NOEU'},
                   DEFORMATION = {'EPSI_ELGA', 'EPSI_ELNO', 'EPSI_NOEU', 'EPSG_ELGA'},
                   CRITERES = {'SIEQ_ELGA', 'SIEQ_ELNO', 'SIEQ_NOEU'}, FORCE = {'REAC_NODA'}}
    for _, t in ipairs({0.5, 1.0}) do
      local sig, eps, epsg, sieq = exact(modelisation, t)
      local ss, es = 3.0 * t, math.abs(eps.EPXX) + math.abs(eps.EPYY)
      local w = what .. ' t=' .. t
      if option == 'SIEF_ELGA' then checkField(R, 'SIEF_ELGA', t, sig, ss, w, 4 * cells * points) end
      checkField(R, 'SIGM_ELGA', t, sig, ss, w, 4 * cells * points)
      checkField(R, 'SIEF_ELNO', t, sig, ss, w, 4 * cells * nodes)
      checkField(R, 'SIGM_ELNO', t, sig, ss, w, 4 * cells * nodes)
      checkField(R, 'SIEF_NOEU', t, sig, ss, w, 4 * MA:getNumberOfNodes())
      checkField(R, 'SIGM_NOEU', t, sig, ss, w, 4 * MA:getNumberOfNodes())
      checkField(R, 'EPSI_ELGA', t, eps, es, w, 4 * cells * points)
      checkField(R, 'EPSI_ELNO', t, eps, es, w, 4 * cells * nodes)
      checkField(R, 'EPSI_NOEU', t, eps, es, w, 4 * MA:getNumberOfNodes())
      checkField(R, 'EPSG_ELGA', t, epsg, es, w, 4 * cells * points)
      checkField(R, 'SIEQ_ELGA', t, sieq, ss, w, 17 * cells * points)
      checkField(R, 'SIEQ_ELNO', t, sieq, ss, w, 17 * cells * nodes)
      checkField(R, 'SIEQ_NOEU', t, sieq, ss, w, 17 * MA:getNumberOfNodes())
    end
    local sig, eps, _, sieq = exact(modelisation, 1.0)
    TEST_RESU{RESU = {
      {RESULTAT = R, INST = 1.0, NOM_CHAM = 'SIGM_ELNO', GROUP_MA = 'CELL1', GROUP_NO = 'NC', NOM_CMP = 'SIXY',
       VALE_CALC = sig.SIXY, REFERENCE = 'ANALYTIQUE', VALE_REFE = sig.SIXY, PRECISION = 1e-10},
      {RESULTAT = R, NUME_ORDRE = 2, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'NC', NOM_CMP = 'SIXX',
       VALE_CALC = sig.SIXX, REFERENCE = 'ANALYTIQUE', VALE_REFE = sig.SIXX, PRECISION = 1e-10},
      {RESULTAT = R, INST = 1.0, NOM_CHAM = 'EPSI_ELGA', MAILLE = 'M1', POINT = points, NOM_CMP = 'EPXY',
       VALE_CALC = eps.EPXY, REFERENCE = 'ANALYTIQUE', VALE_REFE = eps.EPXY, PRECISION = 1e-10},
      {RESULTAT = R, INST = 1.0, NOM_CHAM = 'SIEQ_ELNO', MAILLE = 'M1', POINT = nodes, NOM_CMP = 'VMIS',
       VALE_CALC = sieq.VMIS, REFERENCE = 'ANALYTIQUE', VALE_REFE = sieq.VMIS, PRECISION = 1e-10},
      {RESULTAT = R, INST = 1.0, NOM_CHAM = 'SIGM_ELGA', TYPE_TEST = 'MAX', NOM_CMP = 'SIYY',
       VALE_CALC = sig.SIYY, REFERENCE = 'ANALYTIQUE', VALE_REFE = sig.SIYY, PRECISION = 1e-10},
    }}
    C = CREA_CHAMP{TYPE_CHAM = 'ELNO_SIEF_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'SIEQ_ELNO', INST = 1.0}
    G = CREA_CHAMP{TYPE_CHAM = 'ELGA_EPSI_R', OPERATION = 'EXTR', RESULTAT = R, NOM_CHAM = 'EPSI_ELGA', INST = 1.0}
    TEST_RESU{CHAM_ELEM = {
      {CHAM_GD = C, GROUP_MA = 'CELL1', NOEUD = 'N1', NOM_CMP = 'TRESCA',
       VALE_CALC = sieq.TRESCA, REFERENCE = 'ANALYTIQUE', VALE_REFE = sieq.TRESCA, PRECISION = 1e-10},
      {CHAM_GD = G, MAILLE = 'M1', POINT = 1, SOUS_POINT = 1, NOM_CMP = 'EPZZ',
       VALE_CALC = eps.EPZZ, REFERENCE = 'ANALYTIQUE', VALE_REFE = eps.EPZZ, PRECISION = 1e-10,
       CRITERE = eps.EPZZ == 0 and 'ABSOLU' or 'RELATIF', ORDRE_GRANDEUR = eps.EPZZ == 0 and 1.0 or nil},
    }}
    DETRUIRE{CONCEPT = {NOM = {C, G}}}
  end
end
print('CALC_CHAMP PATCH: every check passed')
