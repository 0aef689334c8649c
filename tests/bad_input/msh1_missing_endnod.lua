-- expect-exit: 2
-- expect-output: <F> <LIRE_MAILLAGE> .*msh1_missing_endnod\.lua:5: .*msh1_missing_endnod\.msh:7: expected \$ENDNOD, found '\$ELM' \(expected a gmsh MSH 1 file, \$NOD \.\.\. \$ENDELM, or MSH 2 ASCII
-- A GMSH file in the old MSH 1 format whose nodes section is not closed by $ENDNOD.
DEBUT{}
MA = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 20}
FIN{}
