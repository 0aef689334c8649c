-- Adds the keywords of a check (computed value, reference, tolerances) to a factor
-- keyword. Without REFERENCE (NON_REGRESSION) the value is compared with VALE_CALC
-- within TOLE_MACHINE; with a reference, also with VALE_REFE within PRECISION.
local function with_check(fact)
  local keys = {
    SIMP{ 'VALE_CALC', statut = 'o', typ = 'R', fr = "Value computed by this program (non-regression)." },
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
      SIMP{ 'VALE_REFE', statut = 'o', typ = 'R', fr = "Reference value." },
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

return PROC{ nom = 'TEST_FONCTION',
  fr = "Checks values of functions against expected values; prints OK or NOOK for each.",
  with_check(FACT{ 'VALEUR', statut = 'o', max = '**', fr = "Checks the value of a function at a point.",
    SIMP{ 'FONCTION', statut = 'o', typ = {'fonction_sdaster', 'formule', 'nappe_sdaster'}, fr = "The function." },
    SIMP{ 'NOM_PARA', typ = 'TXM', max = 2, fr = "Names of the parameters (default: the function's)." },
    SIMP{ 'VALE_PARA', statut = 'o', typ = 'R', max = 2, fr = "Values of the parameters." },
  }),
}
