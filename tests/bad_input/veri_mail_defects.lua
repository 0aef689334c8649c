-- expect-exit: 2
-- expect-output: <A> <LIRE_MAILLAGE> .*veri_mail_defects\.lua:6: .*veri_mail_defects\.mail: 1 node belongs to no cell \(orphan\): N7.*<A> <LIRE_MAILLAGE> .*: 1 cell has the same nodes as another .*: M1 \(QUAD4 of SURFACE\) and M8 \(QUAD4\).*<A> <LIRE_MAILLAGE> .*: 1 cell is flattened or degenerate .*APLAT = 0\.001\): M2 \(QUAD4 of SURFACE\): ratio 7\.07e-05.*<F> <LIRE_MAILLAGE> .*veri_mail_defects\.lua:6: .*veri_mail_defects\.mail: 1 cell has a node repeated in its connectivity .*: M9 \(TRIA3\): node N2 twice
-- VERI_MAIL (on by default) names each defect of the mesh: alarms for the
-- orphan node, the double cell and the flattened one, a fatal error for the
-- cell with a repeated node, as code_aster's LIRE_MAILLAGE.
MA = LIRE_MAILLAGE{FORMAT = 'ASTER', UNITE = 20}
FIN{}
