-- Verification: a thick cylinder under internal pressure, elastic-perfectly
-- plastic von Mises, plane strain (D_PLAN, QUAD8), against Hill's solution
-- (R. Hill, The Mathematical Theory of Plasticity, 1950, ch. V). Inner radius
-- a = 1, outer b = 2, E = 210000, NU = 0.3, SY = 240, k = SY / sqrt(3).
--
-- Hill (plastic zone a <= r <= c, sigma_z the mean of sigma_r and sigma_theta):
--   sigma_r = -p + 2 k ln(r / a),  sigma_theta = sigma_r + 2 k        (a <= r <= c)
--   sigma_r = -k c^2/b^2 (b^2/r^2 - 1),  sigma_theta = k c^2/b^2 (b^2/r^2 + 1)   (c <= r <= b)
--   p = k (1 - c^2/b^2 + 2 ln(c / a)),   limit pressure p_L = 2 k ln(b / a).
-- The hoop stress on the outer surface, 2 k c^2 / b^2, measures the plastic radius c.
--
-- Mesh: thick_cylinder_hill.mail (bench/thick_cylinder.py 4 10: a quarter, 4 x 10
-- QUAD8, nodes on the exact circles), refined three times (32 x 80 cells). Part 1 raises
-- the pressure to the p of c = 1.5 in 10 steps; part 2 drives the inner radius out
-- to 10 times the displacement at first yield, where the pressure (the reactions on
-- the inner edge) approaches p_L.
-- Tolerances: 0.5 %, for Hill's assumption on sigma_z (NU = 0.3 departs from it:
-- a bigger plastic zone, by about 0.1 % in c) and the nodal stresses extrapolated
-- from the Gauss points; part 2 also stops at a finite displacement, where the
-- pressure is still below p_L. Found: 0.007 %, 0.04 %, 0.05 % and 0.12 % below p_L.
-- VALE_CALC: aster-lite's values (non-regression).
DEBUT()
local A, B, E, NU, SY = 1.0, 2.0, 210000.0, 0.3, 240.0
local k = SY / math.sqrt(3)
local c = 1.5
local P1 = k * (1 - c * c / (B * B) + 2 * math.log(c / A))
local PL = 2 * k * math.log(B / A)

MA0 = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA0, MAILLAGE_NP1 = CO('MA1')}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA1, MAILLAGE_NP1 = CO('MA2')}
MACR_ADAP_MAIL{ADAPTATION = 'RAFFINEMENT_UNIFORME', MAILLAGE_N = MA2, MAILLAGE_NP1 = CO('MAIL')}
MAIL = DEFI_GROUP{reuse = MAIL, MAILLAGE = MAIL, CREA_GROUP_NO = {{GROUP_MA = 'INT'}, {GROUP_MA = 'BAS'}}}
MODELE = AFFE_MODELE{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
ACIER = DEFI_MATERIAU{ELAS = {E = E, NU = NU}, ECRO_LINE = {D_SIGM_EPSI = 0.0, SY = SY}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
SYMETRIE = AFFE_CHAR_MECA{MODELE = MODELE, DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
RAMPE = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}

-- Part 1: pressure control, up to c = 1.5.
PRESSION = AFFE_CHAR_MECA{MODELE = MODELE, PRES_REP = {GROUP_MA = 'INT', PRES = P1}}
L10 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 10}}
RESU = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT,
                     EXCIT = {{CHARGE = SYMETRIE}, {CHARGE = PRESSION, FONC_MULT = RAMPE}},
                     COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE'}, INCREMENT = {LIST_INST = L10}}
RESU = CALC_CHAMP{reuse = RESU, RESULTAT = RESU, CONTRAINTE = 'SIGM_NOEU', VARI_INTERNE = 'VARI_NOEU'}
TEST_RESU{RESU = {
  -- the inner surface (A, r = a, theta = 0: x radial, y hoop), in the plastic zone
  {RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'A', NOM_CMP = 'SIXX',
   REFERENCE = 'ANALYTIQUE', VALE_REFE = -P1, VALE_CALC = -172.99907599766857, PRECISION = 0.005},
  {RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'A', NOM_CMP = 'SIYY',
   REFERENCE = 'ANALYTIQUE', VALE_REFE = -P1 + 2 * k, VALE_CALC = 104.17939577352215, PRECISION = 0.005},
  -- the outer surface (B, r = b): sigma_theta = 2 k c^2 / b^2, i.e. the plastic radius c
  {RESULTAT = RESU, INST = 1.0, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'B', NOM_CMP = 'SIYY',
   REFERENCE = 'ANALYTIQUE', VALE_REFE = 2 * k * c * c / (B * B), VALE_CALC = 155.96258741799736, PRECISION = 0.005},
}}

-- The radial and hoop stresses along Y = 0 and the cumulated plastic strain, for
-- docs/verification/plasticity.md's plot (PROFIL.tab in the output folder).
PROFIL = POST_RELEVE_T{ACTION = {OPERATION = 'EXTRACTION', INTITULE = 'BAS', RESULTAT = RESU, INST = 1.0,
                                 NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'BAS', NOM_CMP = {'SIXX', 'SIYY', 'SIZZ'}}}
IMPR_TABLE{TABLE = PROFIL}

-- Part 2: the inner radius driven out to 10 times its displacement at first yield
-- (u_a = (1 + NU)/E p_e a^2/(b^2 - a^2) ((1 - 2 NU) a + b^2 / a), p_e = k (1 - a^2/b^2)).
local pe = k * (1 - A * A / (B * B))
local ue = (1 + NU) / E * pe * A * A / (B * B - A * A) * ((1 - 2 * NU) * A + B * B / A)
UR = FORMULE{VALE = 'U * X', NOM_PARA = {'X', 'INST'}, U = 10 * ue}
UT = FORMULE{VALE = 'U * Y', NOM_PARA = {'Y', 'INST'}, U = 10 * ue}
RAYON = AFFE_CHAR_MECA_F{MODELE = MODELE, DDL_IMPO = {GROUP_MA = 'INT', DX = UR, DY = UT}}
L20 = DEFI_LIST_REEL{DEBUT = 0.0, INTERVALLE = {JUSQU_A = 1.0, NOMBRE = 20}}
LIMITE = STAT_NON_LINE{MODELE = MODELE, CHAM_MATER = CHMAT,
                       EXCIT = {{CHARGE = SYMETRIE}, {CHARGE = RAYON, FONC_MULT = RAMPE}},
                       COMPORTEMENT = {RELATION = 'VMIS_ISOT_LINE'}, INCREMENT = {LIST_INST = L20}}
LIMITE = CALC_CHAMP{reuse = LIMITE, RESULTAT = LIMITE, FORCE = 'REAC_NODA'}
-- The x resultant of the reactions on the quarter inner edge is p a (the pressure
-- integrated over the quarter circle against cos theta).
FORCE = POST_RELEVE_T{ACTION = {OPERATION = 'EXTRACTION', INTITULE = 'INT', RESULTAT = LIMITE,
                                NOM_CHAM = 'REAC_NODA', GROUP_NO = 'INT', RESULTANTE = 'DX'}}
TEST_TABLE{TABLE = FORCE, NOM_PARA = 'DX', FILTRE = {NOM_PARA = 'INST', VALE = 1.0},
           REFERENCE = 'ANALYTIQUE', VALE_REFE = PL * A, VALE_CALC = 191.8618958166507, PRECISION = 0.005}
-- The pressure against the inner displacement (u_a = 10 u_e INST), for the plot (FORCE.tab).
IMPR_TABLE{TABLE = FORCE}
FIN()
