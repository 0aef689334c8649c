-- expect-exit: 2
-- expect-output: <F> <AFFE_MODELE> .*axis_negative_radius\.lua:7: MODELISATION='AXIS': cell M1 \(QUAD4 of SURFACE\) has node N1 at X = -0\.5 < 0; in AXIS, X is the radius r >= 0
-- In AXIS, X is the radius: a cell reaching X < 0 is refused, by name.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'axis_negative_radius.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
FIN{}
