-- expect-exit: 0
-- expect-output: <I> checks: 5 OK, 0 NOOK
-- FORMULE with other keywords: names the expression uses (code_aster's
-- FORMULE(VALE='A*X', A=A, NOM_PARA='X')). Values by hand:
--   F = A*X with A = 2.5:                F(3) = 7.5, F(-0.4) = -1
--   H = B*G(X + 1) + C(7), G = X**2 + 1,
--       B = 3, C = DEFI_CONSTANTE 0.5:   H(2) = 3*10 + 0.5 = 30.5
--   K = T(INST/2) - 1, T through (0, 0), (2, 4): K(2) = 2 - 1 = 1
--   L = A*F(X): a formula with a context called by another: L(2) = 2.5*5 = 12.5
A = 2.5
F = FORMULE{VALE = 'A*X', A = A, NOM_PARA = 'X'}
G = FORMULE{VALE = 'X**2 + 1', NOM_PARA = 'X'}
C = DEFI_CONSTANTE{VALE = 0.5}
H = FORMULE{VALE = 'B*G(X + 1) + C(7)', G = G, B = 3, C = C, NOM_PARA = 'X'}
T = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 2.0, 4.0}}
K = FORMULE{VALE = 'T(INST/2) - 1', T = T, NOM_PARA = 'INST'}
L = FORMULE{VALE = 'A*F(X)', A = A, F = F, NOM_PARA = 'X'}
local exact = {CRITERE = 'ABSOLU', PRECISION = 0.0, REFERENCE = 'ANALYTIQUE'}
local function check(f, x, v)
  local c = {FONCTION = f, VALE_PARA = x, VALE_CALC = v, VALE_REFE = v}
  for key, value in pairs(exact) do c[key] = value end
  return c
end
TEST_FONCTION{VALEUR = {check(F, 3.0, 7.5), check(F, -0.4, -1.0), check(H, 2.0, 30.5), check(K, 2.0, 1.0),
                        check(L, 2.0, 12.5)}}
FIN{}
