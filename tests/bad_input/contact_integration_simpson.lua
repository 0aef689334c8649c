-- expect-exit: 2
-- expect-output: <F> <DEFI_CONTACT> .*contact_integration_simpson\.lua:8: ZONE\[1\]: keyword INTEGRATION = .SIMPSON. is not allowed. allowed values: .GAUSS., .AUTO.
-- Only the GAUSS and AUTO contact integrations exist.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'contact_block.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MO = AFFE_MODELE{MAILLAGE = MA, AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'D_PLAN'}}
CT = DEFI_CONTACT{MODELE = MO, FORMULATION = 'CONTINUE', ZONE = {GROUP_MA_MAIT = 'MAITRE', GROUP_MA_ESCL = 'BAS', INTEGRATION = 'SIMPSON'}}
