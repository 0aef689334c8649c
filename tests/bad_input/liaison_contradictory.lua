-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*liaison_contradictory\.lua:12: LIAISON_UNIF\[1\]: this linear relation contradicts the imposed displacements and the relations before it \(its two sides differ by 0\.001\)
-- u_x(N5) = u_x(N6) (LIAISON_DDL 1), u_x(N4) - u_x(N6) = 1e-3 (LIAISON_DDL 2) and
-- u_x(N4) = u_x(N5) (LIAISON_UNIF, read after the LIAISON_DDL): the last follows from the
-- first two but for its value.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
BC = AFFE_CHAR_MECA{MODELE = MO, LIAISON_UNIF = {NOEUD = {'N4', 'N5'}, DDL = 'DX'},
  LIAISON_DDL = {{NOEUD = {'N5', 'N6'}, DDL = {'DX', 'DX'}, COEF_MULT = {1.0, -1.0}, COEF_IMPO = 0.0},
                 {NOEUD = {'N4', 'N6'}, DDL = {'DX', 'DX'}, COEF_MULT = {1.0, -1.0}, COEF_IMPO = 1e-3}}}
FIN{}
