#!/usr/bin/env python3
"""Derives, once and outside aster-lite, the loads of SSNP150 modelization B
(E = 1, NU = 0.3, D_PLAN, Saint Venant-Kirchhoff) as Python-syntax formula strings, as
the reference study does with sympy. Its output is pasted into
studies/ssnp150b_formules.lua. Not part of the build: run by hand with sympy.
"""
from sympy import Matrix, Rational, diff, eye, sqrt, symbols

X, Y = symbols("X Y", real=True)
half = Rational(1, 2)
U = Matrix([-Rational(1, 5) * Y**3 * (X - half),
            -Rational(1, 20) * (X - half)**2 * (1 + Y) - Rational(1, 100) * Y])
gradU = Matrix(2, 2, lambda i, j: diff(U[i], (X, Y)[j]))
F = eye(2) + gradU
E, nu = 1, Rational(3, 10)
lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
Egl = (F.T * F - eye(2)) / 2
Pi = F * (lam * Egl.trace() * eye(2) + 2 * mu * Egl)


def out(name, expr, expand=True):
    e = expr.expand() if expand else expr
    print("%s = '%s'" % (name, str(e.evalf(17)).replace(" ", "")))


for i, c in enumerate("XY"):
    out("FV" + c, -(diff(Pi[i, 0], X) + diff(Pi[i, 1], Y)))
for edge, N in (("DROITE", Matrix([1, 0])), ("GAUCHE", Matrix([-1, 0]))):
    t = Pi * N
    for i, c in enumerate("XY"):
        out("F%s_%s" % (c, edge), t[i])
N = Matrix([0, -1])
m = F.inv().T * N
n = m / sqrt(m[0]**2 + m[1]**2)
t = Pi * N
p = (t.T * n)[0]
tt = t - p * n
for i, c in enumerate("XY"):
    out("F%s_BAS_T" % c, tt[i], expand=False)
out("PRES", p, expand=False)
