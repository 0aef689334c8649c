-- expect-exit: 2
-- expect-output: <F> <IMPR_FONCTION> .*sandbox_unit_outside\.lua:10: UNITE=30 is bound by DEFI_FICHIER to .*sandbox_unit_outside\.txt, outside the output folder .*: a study writes only below its output folder
-- A sandboxed study cannot write outside its output folder through a command
-- either: a unit it binds with DEFI_FICHIER to a file elsewhere is refused
-- for writing (here the file would land in tests/, next to the corpus).
F = DEFI_FONCTION{NOM_PARA = 'INST', VALE = {0.0, 0.0, 1.0, 1.0}}
DEFI_FICHIER{ACTION = 'ASSOCIER', UNITE = 30, FICHIER = '../sandbox_unit_outside.txt'}
-- A unit given by the user on the command line (-u) stays writable anywhere;
-- this one is the study's own choice.
IMPR_FONCTION{FORMAT = 'TABLEAU', UNITE = 30, TITRE = 'x', COURBE = {FONCTION = F}}
FIN{}
