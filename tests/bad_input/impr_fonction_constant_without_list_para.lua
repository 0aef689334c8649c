-- expect-exit: 2
-- expect-output: <F> <IMPR_FONCTION> .*impr_fonction_constant_without_list_para\.lua:6: COURBE\[1\]: C is a constant \(DEFI_CONSTANTE\): give LIST_PARA, the abscissas to draw it at
-- A constant function has no points of its own: a curve of it needs LIST_PARA.
DEBUT{}
C = DEFI_CONSTANTE{VALE = 1.0}
IMPR_FONCTION{FORMAT = 'TABLEAU', COURBE = {FONCTION = C}}
FIN{}
