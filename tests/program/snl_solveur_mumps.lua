-- expect-exit: 0
-- expect-output: linear solver MUMPS, RENUM='SCOTCH' \(ordering used: SCOTCH\).*MUMPS: every check passed
-- METHODE='MUMPS' is Debian's MUMPS, not an alias: SSNP150 A (studies/ssnp150a.lua: 256
-- QUAD8, Saint Venant-Kirchhoff, GROT_GDEP, DISCRETE contact: stiffness + Lagrange
-- multipliers, a symmetric indefinite system) solved with MUMPS (its AUTO ordering and
-- SCOTCH, TYPE_RESOL AUTO and NONSYM) and with MULT_FRONT gives the same displacement at
-- every node to 1e-12 relative (both factorizations are exact to round-off; Newton stops
-- at the same iterations). tests/bad_input/snl_mumps_*.lua: what MUMPS refuses.
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = '../../studies/ssnp150a.med'}
MAIL = LIRE_MAILLAGE{FORMAT = 'MED', UNITE = 20}
MAIL = MODI_MAILLAGE{reuse = MAIL, MAILLAGE = MAIL, ORIE_PEAU = {{GROUP_MA_PEAU = 'MAITRE'}, {GROUP_MA_PEAU = 'BAS'}}}
MODELE = AFFE_MODELE{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
UX = FORMULE{VALE = '-0.2*Y**3*(X-0.5)', NOM_PARA = {'X', 'Y'}}
UY = FORMULE{VALE = '-0.05*(X-0.5)**2*(1+Y) - 0.01*Y', NOM_PARA = {'X', 'Y'}}
MMS = CALC_SOLU_MANU{DEPL = {DX = UX, DY = UY}, MATER = ACIER, MODELISATION = 'D_PLAN',
                     DEFORMATION = 'GROT_GDEP', MAILLAGE = MAIL,
                     BORD = {{NOM = 'DROITE', NORMALE = {1, 0}},
                             {NOM = 'GAUCHE', NORMALE = {-1, 0}},
                             {NOM = 'BAS', NORMALE = {0, -1}, CONTACT = 'OUI'}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0, 0, 1, 1}, PROL_GAUCHE = 'LINEAIRE', PROL_DROITE = 'LINEAIRE'}
DEPL_IMP = AFFE_CHAR_MECA_F{MODELE = MODELE, DDL_IMPO = {GROUP_MA = 'HAUT', DX = UX, DY = UY}}
FORC_SUR = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_CONTOUR = {
  {GROUP_MA = 'DROITE', FX = MMS.DROITE.FX, FY = MMS.DROITE.FY},
  {GROUP_MA = 'GAUCHE', FX = MMS.GAUCHE.FX, FY = MMS.GAUCHE.FY},
  {GROUP_MA = 'BAS', FX = MMS.BAS.FX_T, FY = MMS.BAS.FY_T}}}
FORC_VOL = AFFE_CHAR_MECA_F{MODELE = MODELE, FORCE_INTERNE = {
  GROUP_MA = 'SURFACE', FX = MMS.FORCE_INTERNE.FX, FY = MMS.FORCE_INTERNE.FY}}
BLOCAGE = AFFE_CHAR_CINE{MODELE = MODELE, MECA_IMPO = {GROUP_MA = 'MAITRE', DX = 0.0, DY = 0.0}}
CONTACT = DEFI_CONTACT{MODELE = MODELE, FORMULATION = 'DISCRETE', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}
LINST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 4}}

local function solve(solveur)
  local R = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT,
    EXCIT = {{CHARGE = DEPL_IMP, FONC_MULT = RAMPE}, {CHARGE = FORC_SUR, FONC_MULT = RAMPE},
             {CHARGE = FORC_VOL, FONC_MULT = RAMPE}, {CHARGE = BLOCAGE}},
    CONTACT = CONTACT, COMPORTEMENT = {RELATION = 'ELAS', DEFORMATION = 'GROT_GDEP'},
    INCREMENT = {LIST_INST = LINST}, CONVERGENCE = {RESI_GLOB_RELA = 1e-10, ITER_GLOB_MAXI = 30},
    SOLVEUR = solveur, INFO = 2}
  return R:getField('DEPL', 1.0):getValues()
end

local reference = solve({METHODE = 'MULT_FRONT'})
local scale = 0.0
for _, v in ipairs(reference) do scale = math.max(scale, math.abs(v)) end
if scale < 1e-3 then error('MULT_FRONT: no displacement') end
for _, solveur in ipairs({{METHODE = 'MUMPS'}, {METHODE = 'MUMPS', RENUM = 'SCOTCH'},
                          {METHODE = 'MUMPS', RENUM = 'PORD', TYPE_RESOL = 'NONSYM', RESI_RELA = 1e-10}}) do
  local u = solve(solveur)
  if #u ~= #reference then error(string.format('%d values, MULT_FRONT %d', #u, #reference)) end
  for i = 1, #u do
    if not (math.abs(u[i] - reference[i]) <= 1e-12 * scale) then
      error(string.format('MUMPS RENUM=%s: value %d is %.17g, MULT_FRONT %.17g', solveur.RENUM or 'AUTO', i, u[i],
                          reference[i]))
    end
  end
end

print('MUMPS: every check passed')
