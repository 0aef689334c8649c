-- expect-exit: 2
-- expect-output: <F> <MECA_STATIQUE> .*liaison_contradictory_loads\.lua:14: AFFE_CHAR_MECA \(.*liaison_contradictory_loads\.lua:11\) LIAISON_UNIF\[1\]: this linear relation contradicts the imposed displacements and the relations before it \(its two sides differ by -0\.002 at INST = 0\)
-- Each load is consistent alone; together DY = 0 on BAS and DY = 2e-3 at N3 contradict
-- LIAISON_UNIF DY on N1, N3 (found by the analysis, which names where the relation was defined).
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
MAT = DEFI_MATERIAU{ELAS = {E = 1000.0, NU = 0.3}}
CM = AFFE_MATERIAU{MAILLAGE = MA, AFFE = {TOUT = 'OUI', MATER = MAT}}
REL = AFFE_CHAR_MECA{MODELE = MO, LIAISON_UNIF = {NOEUD = {'N1', 'N3'}, DDL = 'DY'}}
BC = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {{GROUP_MA = 'GAUCHE', DX = 0.0}, {NOEUD = 'N1', DY = 0.0},
                                             {NOEUD = 'N3', DY = 2e-3}}}
R = MECA_STATIQUE{MODELE = MO, CHAM_MATER = CM, EXCIT = {{CHARGE = BC}, {CHARGE = REL}}}
FIN{}
