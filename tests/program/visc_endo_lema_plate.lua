-- expect-exit: 0
-- expect-output: STAT_NON_LINE: 200 instants, 200 Newton iterations.*<I> checks: 6 OK, 0 NOOK
-- VISC_ENDO_LEMA on code_aster's ssnp101a problem (its second computation, written anew):
-- the unit square, one QUAD4 in D_PLAN, held at N4 (DX, DY) and N3 (DX), under nodal forces
-- that grow linearly to t = 30 s (tension and shear, a homogeneous state), 200 equal steps,
-- ELAS E = 178600, NU = 0.3, LEMAITRE N = 11, UN_SUR_K = 3.2840723e-4, UN_SUR_M = 0.178571429,
-- VISC_ENDO SY = 0, R_D = 3, A_D = 1e5. Outside checks at t = 30 s, node N2:
--  - code_aster's own results (ssnp101a's VALE_CALC): EPSP_ELNO EPXX = 1.77275564e-4 and
--    EPXY = 1.82685086e-4, to 1e-5 (aster-lite differs by 2.5e-7 and 1.2e-7);
--  - ssnp101a's reference (another code_aster computation, LEMAITRE with PARM_THETA = 0.5):
--    EPXX = 1.762e-4, EPXY = 1.816e-4 to 0.7%, as code_aster checks them.
-- The viscoplastic strain of the internal variables: V1 (EPSPXX) is EPSP_ELNO's EPXX less the
-- damage's share D/(1 - D) of the elastic strain (D ~ 1.7e-7: 1e-6 relative), V4 (EPSPXY) is
-- sqrt(2) EPXY (code_aster stores this law's shear components so).
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
U = STAT_NON_LINE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = CH1}, {CHARGE = CH2}},
                  COMPORTEMENT = {RELATION = 'VISC_ENDO_LEMA', ALGO_INTE = 'BRENT', ITER_INTE_MAXI = 20},
                  INCREMENT = {LIST_INST = L_INST, INST_FIN = 30.0},
                  NEWTON = {PREDICTION = 'EXTRAPOLE', MATRICE = 'TANGENTE', REAC_ITER = 1},
                  CONVERGENCE = {RESI_GLOB_RELA = 1e-06, ITER_GLOB_MAXI = 25}}
U = CALC_CHAMP{reuse = U, RESULTAT = U, DEFORMATION = {'EPSP_ELNO'}, VARI_INTERNE = {'VARI_ELNO'}}
local function at(field, component, calc, reference, precision)
  return {INST = 30.0, RESULTAT = U, NOM_CHAM = field, NOEUD = 'N2', MAILLE = 'M1', NOM_CMP = component,
          VALE_CALC = calc, REFERENCE = 'AUTRE_ASTER', VALE_REFE = reference, PRECISION = precision}
end
TEST_RESU{RESU = {
  at('EPSP_ELNO', 'EPXX', 1.77275609e-4, 1.77275564e-4, 1e-5),
  at('EPSP_ELNO', 'EPXY', 1.82685107e-4, 1.82685086e-4, 1e-5),
  at('EPSP_ELNO', 'EPXX', 1.77275609e-4, 1.762e-4, 7e-3),
  at('EPSP_ELNO', 'EPXY', 1.82685107e-4, 1.816e-4, 7e-3),
  at('VARI_ELNO', 'V1', 1.77275432e-4, 1.77275564e-4, 1e-5),
  at('VARI_ELNO', 'V4', 2.58355548e-4, 1.4142135623730951 * 1.82685086e-4, 1e-5),
}}
