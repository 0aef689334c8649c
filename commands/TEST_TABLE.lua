-- Adds the keywords of a check (computed value, reference, tolerances) to a command
-- or factor keyword. Without REFERENCE (NON_REGRESSION) the value is compared with VALE_CALC
-- within TOLE_MACHINE; with a reference, also with VALE_REFE within PRECISION.
local function with_check(fact)
  local keys = {
    SIMP{ 'VALE_CALC', typ = 'R', fr = "Real value computed by this program (non-regression)." },
    SIMP{ 'VALE_CALC_I', typ = 'I', fr = "Integer value computed by this program." },
    SIMP{ 'VALE_CALC_K', typ = 'TXM', fr = "Text value computed by this program." },
    SIMP{ 'VALE_ABS', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'},
          fr = "OUI: compare the absolute value." },
    SIMP{ 'TOLE_MACHINE', typ = 'R', defaut = 1.0e-6, val_min = 0.0,
          fr = "Tolerance of the comparison with VALE_CALC." },
    SIMP{ 'CRITERE', typ = 'TXM', defaut = 'RELATIF', into = {'RELATIF', 'ABSOLU'},
          fr = "Relative or absolute tolerances." },
    SIMP{ 'REFERENCE', typ = 'TXM', defaut = 'NON_REGRESSION',
          into = {'NON_REGRESSION', 'ANALYTIQUE', 'SOURCE_EXTERNE', 'AUTRE_ASTER', 'NON_DEFINI'},
          fr = "Origin of the reference value (NON_REGRESSION: none but VALE_CALC)." },
    BLOC{ 'b_reference', condition = { REFERENCE = {'ANALYTIQUE', 'SOURCE_EXTERNE', 'AUTRE_ASTER', 'NON_DEFINI'} },
      regles = { UN_PARMI('VALE_REFE', 'VALE_REFE_I', 'VALE_REFE_K') },
      SIMP{ 'VALE_REFE', typ = 'R', fr = "Real reference value." },
      SIMP{ 'VALE_REFE_I', typ = 'I', fr = "Integer reference value." },
      SIMP{ 'VALE_REFE_K', typ = 'TXM', fr = "Text reference value." },
      SIMP{ 'PRECISION', typ = 'R', defaut = 1.0e-3, val_min = 0.0,
            fr = "Tolerance of the comparison with VALE_REFE." },
    },
    SIMP{ 'ORDRE_GRANDEUR', typ = 'R', val_min = 0.0,
          fr = "Magnitude used for an absolute comparison when VALE_CALC is (nearly) zero." },
    SIMP{ 'LEGENDE', typ = 'TXM', defaut = 'XXXX', fr = "Label of the check in the output." },
  }
  for _, k in ipairs(keys) do fact[#fact + 1] = k end
  return fact
end

return with_check(PROC{ nom = 'TEST_TABLE',
  fr = "Checks a value of a table (one cell after filtering, or a sum or extreme of a column); prints OK or NOOK.",
  regles = { UN_PARMI('VALE_CALC', 'VALE_CALC_I', 'VALE_CALC_K') },
  SIMP{ 'TABLE', statut = 'o', typ = 'table_sdaster', fr = "The table." },
  SIMP{ 'NOM_PARA', statut = 'o', typ = 'TXM', fr = "The column tested." },
  SIMP{ 'TYPE_TEST', typ = 'TXM', into = {'SOMM_ABS', 'SOMM', 'MAX', 'MIN'},
        fr = "Over the remaining rows: sum of absolute values, sum, largest or smallest value." },
  FACT{ 'FILTRE', max = '**', fr = "Keeps only the rows meeting a condition (all conditions must hold).",
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
  },
})
