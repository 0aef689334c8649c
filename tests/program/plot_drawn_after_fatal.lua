-- expect-exit: 2
-- expect-output: plot written to .*fonction_1\.png.*<F> <DEFI_LIST_REEL> .*plot_drawn_after_fatal\.lua:5:
-- A fatal error after IMPR_FONCTION: the plot is still drawn at the end of the run.
IMPR_FONCTION{FORMAT = 'PNG', COURBE = {ABSCISSE = {1, 2}, ORDONNEE = {1, 4}}}
L = DEFI_LIST_REEL{DEBUT = 1.0, INTERVALLE = {JUSQU_A = 0.0, NOMBRE = 2}}
