-- expect-exit: 2
-- expect-output: <F> <AFFE_CHAR_MECA> .*maille_absent\.lua:8: PRES_REP\[1\]/MAILLE: cell 'M33' not found in the mesh; did you mean 'M3', 'M1' or 'M2'\?
-- A cell named in MAILLE that the mesh lacks: the command, the keyword, the name and the closest names.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CH = AFFE_CHAR_MECA{MODELE = MO, DDL_IMPO = {GROUP_MA = 'BAS', DX = 0.0, DY = 0.0},
                    PRES_REP = {MAILLE = {'M3', 'M33'}, PRES = 1.0}}
FIN{}
