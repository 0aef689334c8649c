return OPER{ nom = 'AFFE_CHAR_MECA_F', sd_prod = 'char_meca', reentrant = 'n',
  fr = "Defines mechanical loads and Dirichlet conditions whose values are functions of space (X, Y) and time (INST).",
  regles = { AU_MOINS_UN('DDL_IMPO', 'FACE_IMPO', 'LIAISON_DDL', 'LIAISON_UNIF', 'FORCE_NODALE', 'FORCE_CONTOUR',
                         'FORCE_INTERNE', 'PRES_REP') },
  C_CHAR_MECA({'fonction_sdaster', 'formule', 'nappe_sdaster'}),
}
