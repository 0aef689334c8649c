-- expect-exit: 2
-- expect-output: <F> <FIN> no_fin\.lua: the study ends without FIN\{\} \(a study file cut short\?\). the commands before it ran, but the study is not complete
-- A study without FIN.
DEBUT{}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 20, FICHIER = 'base.mail'}
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
