return PROC{ nom = 'DEBUT',
  fr = "Starts a study. Optional in aster-lite: a study may begin with its first command.",
  SIMP{ 'PAR_LOT', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'},
        ignored = "studies always run command by command." },
  FACT{ 'CODE', fr = "code_aster's test-suite header.", ignored = "it only classifies a code_aster test.",
    SIMP{ 'NIV_PUB_WEB', statut = 'o', typ = 'TXM', into = {'INTERNET', 'INTRANET'} },
  },
  C_DEBUT_OPTIONS(),
}
