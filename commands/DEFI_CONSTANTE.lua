return OPER{ nom = 'DEFI_CONSTANTE', sd_prod = 'fonction_sdaster', reentrant = 'n',
  fr = "Defines a constant function: the same value whatever its parameter (NOM_PARA 'TOUTPARA').",
  SIMP{ 'NOM_RESU', typ = 'TXM', defaut = 'TOUTRESU', fr = "Name of the result (ordinate)." },
  SIMP{ 'VALE', statut = 'o', typ = 'R', fr = "The value." },
  SIMP{ 'TITRE', typ = 'TXM', max = '**', fr = "Title of the concept.",
        ignored = "the title of a concept is printed nowhere in aster-lite." },
}
