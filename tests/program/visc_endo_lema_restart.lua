-- expect-exit: 0
-- expect-output: <I> checks: 4 OK, 0 NOOK
-- VISC_ENDO_LEMA restarts from a result: visc_endo_lema_plate.lua's problem computed to
-- t = 15 s, then from that state (ETAT_INIT EVOL_NOLI: displacements, stresses and the 10
-- internal variables) to t = 30 s, ends where the whole run ends (visc_endo_lema_plate.lua's
-- values at t = 30 s, to the equilibrium tolerance), and so does a restart from the fields
-- (ETAT_INIT DEPL, SIGM, VARI extracted at t = 15 s).
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'visc_endo_lema_plate.mail'}
M = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = M, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = 178600.0, NU = 0.3, ALPHA = 0.0},
                      LEMAITRE = {N = 11.0, UN_SUR_K = 0.00032840723, UN_SUR_M = 0.178571429},
                      VISC_ENDO = {SY = 0.0, R_D = 3.0, A_D = 100000.0}}
CM = AFFE_MATERIAU{MAILLAGE = M, AFFE = {TOUT = 'OUI', MATER = ACIER}}
local function ramp(value)
  return DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 30.0, value}, PROL_DROITE = 'LINEAIRE',
                       PROL_GAUCHE = 'LINEAIRE'}
end
P30 = ramp(60.62177826)
M30 = ramp(-60.62177826)
M52M30 = ramp(-165.6217783)
M52P30 = ramp(-44.37822174)
CH1 = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{NOEUD = 'N4', DX = 0.0, DY = 0.0}, {NOEUD = 'N3', DX = 0.0}}}
CH2 = AFFE_CHAR_MECA_F{MODELE = MO, FORCE_NODALE = {
  {NOEUD = 'N2', FX = M52P30, FY = M30}, {NOEUD = 'N3', FX = P30, FY = P30},
  {NOEUD = 'N1', FX = M52M30, FY = M30}, {NOEUD = 'N4', FX = M30, FY = P30}}}
L_INST = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {{JUSQU_A = 30.0, NOMBRE = 200}}}
local function run(init, first, last)
  return STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = CH1}, {CHARGE = CH2}}, ETAT_INIT = init,
                       COMPORTEMENT = {RELATION = 'VISC_ENDO_LEMA'},
                       INCREMENT = {LIST_INST = L_INST, INST_INIT = first, INST_FIN = last},
                       NEWTON = {MATRICE = 'TANGENTE', REAC_ITER = 1},
                       CONVERGENCE = {RESI_GLOB_RELA = 1e-08, ITER_GLOB_MAXI = 25}}
end
U1 = run(nil, 0.0, 15.0)
U2 = run({EVOL_NOLI = U1, INST = 15.0}, 15.0, 30.0)
D15 = CREA_CHAMP{TYPE_CHAM = 'NOEU_DEPL_R', OPERATION = 'EXTR', RESULTAT = U1, NOM_CHAM = 'DEPL', INST = 15.0}
S15 = CREA_CHAMP{TYPE_CHAM = 'ELGA_SIEF_R', OPERATION = 'EXTR', RESULTAT = U1, NOM_CHAM = 'SIEF_ELGA', INST = 15.0}
V15 = CREA_CHAMP{TYPE_CHAM = 'ELGA_VARI_R', OPERATION = 'EXTR', RESULTAT = U1, NOM_CHAM = 'VARI_ELGA', INST = 15.0}
U3 = run({DEPL = D15, SIGM = S15, VARI = V15}, 15.0, 30.0)
U2 = CALC_CHAMP{reuse = U2, RESULTAT = U2, DEFORMATION = {'EPSP_ELNO'}}
U3 = CALC_CHAMP{reuse = U3, RESULTAT = U3, DEFORMATION = {'EPSP_ELNO'}}
local function at(result, component, calc, reference)
  return {INST = 30.0, RESULTAT = result, NOM_CHAM = 'EPSP_ELNO', NOEUD = 'N2', MAILLE = 'M1', NOM_CMP = component,
          VALE_CALC = calc, REFERENCE = 'AUTRE_ASTER', VALE_REFE = reference, PRECISION = 1e-6}
end
TEST_RESU{RESU = {
  at(U2, 'EPXX', 1.77275609e-4, 1.77275609e-4),
  at(U2, 'EPXY', 1.82685107e-4, 1.82685107e-4),
  at(U3, 'EPXX', 1.77275609e-4, 1.77275609e-4),
  at(U3, 'EPXY', 1.82685107e-4, 1.82685107e-4),
}}
