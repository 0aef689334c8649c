-- expect-exit: 2
-- expect-output: <F> <CREA_MAILLAGE> .*crea_maillage_reuse\.lua:7: CREA_MAILLAGE does not accept reuse=
-- CREA_MAILLAGE makes a new mesh (reentrant='n' in code_aster): reuse= is refused.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
MA = CREA_MAILLAGE{reuse = MA, MAILLAGE = MA, LINE_QUAD = {TOUT = 'OUI'}}
