-- Kirsch's problem: an infinite plate with a circular hole (radius a) under a remote
-- tension S along x, in plane stress. The quarter x, y >= 0 of a square of half-width
-- L = 5 a carries the exact Kirsch tractions on its outer edges (so the exact solution
-- of the infinite plate is the exact solution here), with symmetry conditions on the
-- cut edges. In Cartesian components, with r^2 = x^2 + y^2 and t the polar angle:
--   s_xx = S (1 - a^2/r^2 (3/2 cos 2t + cos 4t) + 3/2 a^4/r^4 cos 4t)
--   s_yy = S (  - a^2/r^2 (1/2 cos 2t - cos 4t) - 3/2 a^4/r^4 cos 4t)
--   s_xy = S (  - a^2/r^2 (1/2 sin 2t + sin 4t) + 3/2 a^4/r^4 sin 4t)
-- so that s_xx = 3 S at the top of the hole (A) and s_yy = -S at its side (B).
-- Three nested QUAD8 meshes by gmsh (kirsch.geo, levels 1 to 3). Checks: SIGM_NOEU
-- (CALC_CHAMP) at A and B within 1 % on the finest mesh, and the error at A falling
-- at the rate of the nodal stresses of quadratic elements (h^2: a rate above 1.5).
DEBUT()
S, A = 1.0, 1.0
C2 = FORMULE{VALE = '(X*X - Y*Y)/(X*X + Y*Y)', NOM_PARA = {'X', 'Y'}}
S2 = FORMULE{VALE = '2*X*Y/(X*X + Y*Y)', NOM_PARA = {'X', 'Y'}}
Q = FORMULE{VALE = 'A*A/(X*X + Y*Y)', NOM_PARA = {'X', 'Y'}, A = A}   -- a^2 / r^2
SXX = FORMULE{VALE = 'S*(1 - Q(X,Y)*(1.5*C2(X,Y) + C2(X,Y)**2 - S2(X,Y)**2) + 1.5*Q(X,Y)**2*(C2(X,Y)**2 - S2(X,Y)**2))',
              NOM_PARA = {'X', 'Y'}, S = S, Q = Q, C2 = C2, S2 = S2}
SYY = FORMULE{VALE = 'S*(-Q(X,Y)*(0.5*C2(X,Y) - C2(X,Y)**2 + S2(X,Y)**2) - 1.5*Q(X,Y)**2*(C2(X,Y)**2 - S2(X,Y)**2))',
              NOM_PARA = {'X', 'Y'}, S = S, Q = Q, C2 = C2, S2 = S2}
SXY = FORMULE{VALE = 'S*(-Q(X,Y)*(0.5*S2(X,Y) + 2*S2(X,Y)*C2(X,Y)) + 1.5*Q(X,Y)**2*2*S2(X,Y)*C2(X,Y))',
              NOM_PARA = {'X', 'Y'}, S = S, Q = Q, C2 = C2, S2 = S2}

ACIER = DEFI_MATERIAU{ELAS = {E = 1.0, NU = 0.3}}
local errors = {}
for level = 1, 3 do
  DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 19, FICHIER = 'kirsch_' .. level .. '.msh'}
  local MAIL = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}
  DEFI_FICHIER{ACTION = 'LIBERER', UNITE = 19}
  local MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                             AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}
  local CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}
  local SYM = AFFE_CHAR_MECA{MODELE = MODELE,
                             DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0}, {GROUP_MA = 'GAUCHE', DX = 0.0}}}
  local TRAC = AFFE_CHAR_MECA_F{MODELE = MODELE,
                                FORCE_CONTOUR = {{GROUP_MA = 'DROITE', FX = SXX, FY = SXY},
                                                 {GROUP_MA = 'HAUT', FX = SXY, FY = SYY}}}
  local RESU = MECA_STATIQUE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {{CHARGE = SYM}, {CHARGE = TRAC}}}
  RESU = CALC_CHAMP{reuse = RESU, RESULTAT = RESU, CONTRAINTE = 'SIGM_NOEU'}
  local sigma = RESU:getField('SIGM_NOEU', 0.0)
  local values, components = sigma:getValues(), sigma:getComponents()
  local node = MAIL:getNodes('A')[1]
  errors[level] = math.abs(values[(node - 1) * #components + 1] / (3 * S) - 1)
  if level == 3 then
    TEST_RESU{RESU = {
      {RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'A', NOM_CMP = 'SIXX',
       VALE_CALC = 2.99805397468, VALE_REFE = 3 * S, REFERENCE = 'ANALYTIQUE', PRECISION = 0.01},
      {RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'B', NOM_CMP = 'SIYY',
       VALE_CALC = -0.998154398428, VALE_REFE = -S, REFERENCE = 'ANALYTIQUE', PRECISION = 0.01},
    }}
  end
end
print(string.format('KIRSCH: level 1, error at A %.3e', errors[1]))
for level = 2, 3 do
  local rate = math.log(errors[level - 1] / errors[level]) / math.log(2)
  print(string.format('KIRSCH: level %d, error at A %.3e, rate %.2f', level, errors[level], rate))
  if not (rate > 1.5) then error(string.format('the error at A falls at the rate %.2f, not 2', rate)) end
end
FIN()
