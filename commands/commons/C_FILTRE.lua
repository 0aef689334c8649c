-- FILTRE: the rows of a table a command keeps (RECU_FONCTION, IMPR_TABLE, TEST_TABLE).
function C_FILTRE()
  return FACT{ 'FILTRE', max = '**', fr = "Keeps only the rows meeting a condition (all conditions must hold).",
    SIMP{ 'NOM_PARA', statut = 'o', typ = 'TXM', fr = "Column tested." },
    SIMP{ 'CRIT_COMP', typ = 'TXM', defaut = 'EQ',
          into = {'EQ', 'NE', 'LT', 'LE', 'GT', 'GE', 'VIDE', 'NON_VIDE', 'MAXI', 'MAXI_ABS', 'MINI', 'MINI_ABS'},
          fr = "Comparison with the value(s), emptiness of the cell, or the row of the extreme value." },
    BLOC{ 'b_vale', condition = { CRIT_COMP = {'EQ', 'NE', 'LT', 'LE', 'GT', 'GE'} },
      regles = { UN_PARMI('VALE', 'VALE_I', 'VALE_K') },
      SIMP{ 'VALE', typ = 'R', max = '**', fr = "Real value(s) compared with (EQ: any of them)." },
      SIMP{ 'VALE_I', typ = 'I', max = '**', fr = "Integer value(s) compared with." },
      SIMP{ 'VALE_K', typ = 'TXM', max = '**', fr = "Text value(s) compared with." },
    },
    BLOC{ 'b_crit', condition = { CRIT_COMP = {'EQ', 'NE'} },
      SIMP{ 'CRITERE', typ = 'TXM', defaut = 'RELATIF', into = {'RELATIF', 'ABSOLU'}, fr = "Kind of tolerance for reals." },
      SIMP{ 'PRECISION', typ = 'R', defaut = 1.0e-3, val_min = 0.0, fr = "Tolerance for reals." },
    },
  }
end
