-- Part 2 (after traction_part1.lua): the result R of part 1 checked against the exact
-- solution of uniform plane-strain traction, which four QUAD4 hold exactly:
--   u_x = (1 - NU^2) SX / E x = 0.91 * 2 / 100 * 4 = 0.0728 at P10 (4, 1),
--   u_y = -NU (1 + NU) SX / E y = -0.3 * 1.3 * 2 / 100 * 1 = -0.0078 at P10.
POURSUITE{CODE = 'OUI'}
TEST_RESU{RESU = {
  {RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'P10', NOM_CMP = 'DX', VALE_CALC = 0.0728,
   REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0728, PRECISION = 1e-10},
  {RESULTAT = R, NUME_ORDRE = 1, NOM_CHAM = 'DEPL', GROUP_NO = 'P10', NOM_CMP = 'DY', VALE_CALC = -0.0078,
   REFERENCE = 'ANALYTIQUE', VALE_REFE = -0.0078, PRECISION = 1e-10},
}}
FIN{}
