-- A cantilever in plane stress against the 2D elasticity solution (Timoshenko and
-- Goodier, Theory of Elasticity, art. 21; in the form of Augarde and Deeks, Finite
-- Elements in Analysis and Design 44, 2008): the beam 0 <= x <= L, |y| <= D/2, unit
-- thickness, a parabolic shear traction of resultant P on the end x = L, the exact
-- displacement imposed on the end x = 0 (which makes the solution exact there too).
--   u_x = -P y / (6 E I) ((6 L - 3 x) x + (2 + nu) (y^2 - D^2/4))
--   u_y =  P / (6 E I) (3 nu y^2 (L - x) + (4 + 5 nu) D^2 x / 4 + (3 L - x) x^2)
--   s_xx = -P (L - x) y / I,  s_yy = 0,  s_xy = P (D^2/4 - y^2) / (2 I),  I = D^3 / 12
-- SI units (E = 2.1e11 Pa). QUAD8 meshes by gmsh (cantilever.geo, levels 1 to 3:
-- 20 x 4, 40 x 8, 80 x 16 cells). Checks on each mesh: the tip deflection, the bending
-- stress at the top of the clamped end (SIGM_NOEU), the reactions' sum = -P (1e-10).
-- The errors of a QUAD8 mesh fall as h^2 or faster here (the solution is cubic): the
-- tolerances are a bound of the coarsest mesh's error divided by 4 per level.
DEBUT()
E, NU, P, LB, D = 2.1e11, 0.3, 1.0e6, 10.0, 1.0
I = D ^ 3 / 12
UX = FORMULE{VALE = '-P*Y/(6*E*I)*((6*LB - 3*X)*X + (2 + NU)*(Y*Y - D*D/4))', NOM_PARA = {'X', 'Y'},
             P = P, E = E, I = I, LB = LB, NU = NU, D = D}
UY = FORMULE{VALE = 'P/(6*E*I)*(3*NU*Y*Y*(LB - X) + (4 + 5*NU)*D*D*X/4 + (3*LB - X)*X*X)',
             NOM_PARA = {'X', 'Y'}, P = P, E = E, I = I, LB = LB, NU = NU, D = D}
TXY = FORMULE{VALE = 'P/(2*I)*(D*D/4 - Y*Y)', NOM_PARA = {'X', 'Y'}, P = P, I = I, D = D}
ZERO = DEFI_CONSTANTE{VALE = 0.0}

ACIER = DEFI_MATERIAU{ELAS = {E = E, NU = NU}}
local tipExact = UY(LB, 0.0)
local rootExact = -P * LB * (D / 2) / I
for level = 1, 3 do
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = 'cantilever_' .. level .. '.msh'}
  local MAIL = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
  DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 19}
  local MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                             AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
  local CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
  local CHAR = AFFE_CHAR_MECA_F{MODELE = MODELE,
                                DDL_IMPO = {GROUP_MA = 'ENCAS', DX = UX, DY = UY},
                                FORCE_CONTOUR = {GROUP_MA = 'BOUT', FX = ZERO, FY = TXY}}
  local RESU = MECA_STATIQUE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {CHARGE = CHAR}}
  RESU = CALC_CHAMP{reuse = RESU, RESULTAT = RESU, CONTRAINTE = 'SIGM_NOEU'}
  local scale = 4.0 ^ (1 - level)
  TEST_RESU{RESU = {
    {RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'P', NOM_CMP = 'DY',
     VALE_CALC = tipExact, VALE_REFE = tipExact, REFERENCE = 'ANALYTIQUE', PRECISION = 1e-4 * scale,
     TOLE_MACHINE = 1e-3},
    {RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'HAUT_ENC', NOM_CMP = 'SIXX',
     VALE_CALC = rootExact, VALE_REFE = rootExact, REFERENCE = 'ANALYTIQUE', PRECISION = 1e-3 * scale,
     TOLE_MACHINE = 1e-2},
    {RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'REAC_NODA', TYPE_TEST = 'SOMM', NOM_CMP = 'DY',
     VALE_CALC = -P, VALE_REFE = -P, REFERENCE = 'ANALYTIQUE', PRECISION = 1e-10},
  }}
end
FIN()
