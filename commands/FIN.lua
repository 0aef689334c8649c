return PROC{ nom = 'FIN',
  fr = "Ends the study: prints the summary of the checks. Commands after FIN are not run.",
  SIMP{ 'INFO_RESU', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'}, fr = "Accepted for compatibility." },
  SIMP{ 'RETASSAGE', typ = 'TXM', into = {'OUI', 'NON'}, fr = "Accepted for compatibility." },
}
