return PROC{ nom = 'FIN',
  fr = "Ends the study: prints the summary of the checks. Commands after FIN are not run. When another "
    .. "study file follows in the same run (POURSUITE), FIN ends this file only and the summary comes at the end.",
  SIMP{ 'INFO_RESU', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'}, fr = "Accepted for compatibility." },
  SIMP{ 'RETASSAGE', typ = 'TXM', into = {'OUI', 'NON'}, fr = "Accepted for compatibility." },
}
