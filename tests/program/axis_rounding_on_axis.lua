-- expect-exit: 0
-- expect-output: AXIS ROUNDING: accepted
-- Nodes meant to lie on the axis at X = -1e-17 (a mesher's rounding): AFFE_MODELE
-- accepts the AXIS model (only X < -1e-10 times the mesh's size is refused).
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'axis_rounding_on_axis.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'AXIS'}}
print('AXIS ROUNDING: accepted')
