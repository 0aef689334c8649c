return PROC{ nom = 'TEST_FONCTION',
  fr = "Checks values of functions against expected values; prints OK or NOOK for each.",
  FACT{ 'VALEUR', statut = 'o', max = '**', fr = "Checks the value of a function at a point.",
    SIMP{ 'FONCTION', statut = 'o', typ = {'fonction_sdaster', 'formule', 'nappe_sdaster'}, fr = "The function." },
    SIMP{ 'NOM_PARA', typ = 'TXM', max = 2, fr = "Names of the parameters (default: the function's)." },
    SIMP{ 'VALE_PARA', statut = 'o', typ = 'R', max = 2, fr = "Values of the parameters." },
    C_TEST_REFERENCE{'R'},
  },
}
