-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_lissage_discrete\.lua:8: keyword LISSAGE = .OUI. is not allowed. allowed values: .NON.
-- Smoothed normals (LISSAGE='OUI') exist for FORMULATION='CONTINUE' only: with DISCRETE they are rejected, not ignored.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, LISSAGE = 'OUI', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS'}}
