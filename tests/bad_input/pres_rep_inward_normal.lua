-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*pres_rep_inward_normal\.lua:10: PRES_REP\[1\]/GROUP_MA: the normal of cell M3 \(group HAUT\) points into the cell M1 it bounds \(2 of the 4 edges are reversed\), so the pressure would pull; orient the edges first: MODI_MAILLAGE\{reuse = <mesh>, MAILLAGE = <mesh>, ORIE_PEAU = \{GROUP_MA_PEAU = \{'BAS', 'HAUT'\}\}\} \(VERI_NORM = 'NON' skips this check\)
-- PRES_REP on edges whose normal points into the body (base.mail's HAUT is walked
-- left to right): with VERI_NORM = 'OUI' (the default) the pressure would silently
-- pull; AFFE_CHAR_MECA stops and says how to orient the edges.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
P = AFFE_CHAR_MECA{MODELE = MO, PRES_REP = {GROUP_MA = {'BAS', 'HAUT'}, PRES = 1.0}}
FIN{}
