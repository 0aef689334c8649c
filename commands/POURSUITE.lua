return PROC{ nom = 'POURSUITE',
  fr = "Begins a study file that continues the one run before it in the same run (aster-lite part1.lua "
    .. "part2.lua, or an .export's command files): the concepts of the first file are still there. "
    .. "An error in the first file of a run.",
  SIMP{ 'PAR_LOT', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'},
        fr = "Accepted for compatibility; studies always run command by command." },
  SIMP{ 'LANG', typ = 'TXM', into = {'FR', 'EN'}, fr = "Accepted for compatibility." },
  FACT{ 'CODE', fr = "Accepted for compatibility (code_aster test-suite header).",
    SIMP{ 'NIV_PUB_WEB', typ = 'TXM', into = {'INTERNET', 'INTRANET'} },
  },
  FACT{ 'IMPR_MACRO', fr = "Accepted for compatibility.", SIMP{ 'NIVEAU', typ = 'I' } },
}
