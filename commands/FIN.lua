return PROC{ nom = 'FIN',
  fr = "Ends the study: prints the summary of the checks. Commands after FIN are not run. When another "
    .. "study file follows in the same run (POURSUITE), FIN ends this file only and the summary comes at the end.",
  SIMP{ 'FORMAT_HDF', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'}, fr = "Save code_aster's database as HDF.",
        ignored = "aster-lite keeps no database (results are written by IMPR_RESU)." },
  SIMP{ 'RETASSAGE', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'}, fr = "Compact code_aster's database.",
        ignored = "aster-lite keeps no database." },
  SIMP{ 'INFO_RESU', typ = 'TXM', defaut = 'OUI', into = {'OUI', 'NON'},
        fr = "Print the contents of the results.", ignored = "a listing option." },
  SIMP{ 'PROC0', typ = 'TXM', defaut = 'OUI', into = {'OUI', 'NON'}, fr = "Only processor 0 writes (parallel runs).",
        ignored = "aster-lite runs as one process." },
}
