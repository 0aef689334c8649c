return OPER{ nom = 'AFFE_CHAR_CINE', sd_prod = 'char_cine_meca', reentrant = 'n',
  fr = "Imposes displacements by elimination of the unknowns (kinematic load, no Lagrange multipliers).",
  C_MECA_IMPO('R'),
}
