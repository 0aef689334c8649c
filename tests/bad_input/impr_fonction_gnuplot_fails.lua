-- expect-exit: 2
-- expect-output: <F> <IMPR_FONCTION> .*impr_fonction_gnuplot_fails\.lua:7: gnuplot failed \(see its messages above\)
-- A plot gnuplot cannot draw (abscissas <= 0 on a log axis): the run draws the
-- other plots, then names the IMPR_FONCTION that failed.
DEBUT{}
IMPR_FONCTION{FORMAT = 'PNG', COURBE = {ABSCISSE = {1, 2}, ORDONNEE = {1, 2}}}
IMPR_FONCTION{FORMAT = 'PNG', UNITE = 30, ECHELLE_X = 'LOG', COURBE = {ABSCISSE = {-1, -2}, ORDONNEE = {1, 2}}}
FIN{}
