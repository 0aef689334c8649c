return PROC{ nom = 'POURSUITE',
  fr = "Begins a study file that continues the one run before it in the same run (aster-lite part1.lua "
    .. "part2.lua, or an .export's command files): the concepts of the first file are still there. "
    .. "An error in the first file of a run.",
  SIMP{ 'CODE', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'}, fr = "code_aster's test-suite flag.",
        ignored = "it only classifies a code_aster test." },
  SIMP{ 'FORMAT_HDF', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'},
        fr = "Read code_aster's database saved as HDF.",
        ignored = "aster-lite keeps no database: the concepts of the first file are in memory." },
  C_DEBUT_OPTIONS(),
}
