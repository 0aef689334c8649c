return OPER{ nom = 'AFFE_CHAR_CINE_F', sd_prod = 'char_cine_meca', reentrant = 'n',
  fr = "Imposes displacements, functions of space (X, Y) and time (INST), by elimination of the unknowns (kinematic load, no Lagrange multipliers).",
  C_MECA_IMPO({'fonction_sdaster', 'formule', 'nappe_sdaster'}),
}
