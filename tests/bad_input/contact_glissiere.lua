-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_glissiere\.lua:8: ZONE\[1\]: keyword GLISSIERE = .OUI. is not allowed. allowed values: .NON.
-- Bilateral sliding (GLISSIERE='OUI') is not available: rejected, not ignored.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', GLISSIERE = 'OUI'}}
