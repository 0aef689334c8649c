return OPER{ nom = 'AFFE_CHAR_MECA', sd_prod = 'char_meca', reentrant = 'n',
  fr = "Defines mechanical loads and Dirichlet conditions with constant values.",
  regles = { AU_MOINS_UN('DDL_IMPO', 'FORCE_NODALE', 'FORCE_CONTOUR', 'FORCE_INTERNE', 'PRES_REP') },
  C_CHAR_MECA('R'),
}
