-- expect-exit: 0
-- expect-output: <I> checks: 2 OK, 0 NOOK
-- Every check OK: exit status 0. Values by hand: 0.2*0.7**3*(0.5-0.3) = 0.01372.
F = FORMULE{VALE = '0.2*Y**3*(0.5 - X)', NOM_PARA = {'X', 'Y'}}
TEST_FONCTION{VALEUR = {
  {FONCTION = F, VALE_PARA = {0.3, 0.7}, VALE_CALC = 0.01372},
  {FONCTION = F, VALE_PARA = {0.5, 2.0}, VALE_CALC = 0.0, REFERENCE = 'ANALYTIQUE', VALE_REFE = 0.0,
   CRITERE = 'ABSOLU', PRECISION = 1e-15},
}}
FIN{}
