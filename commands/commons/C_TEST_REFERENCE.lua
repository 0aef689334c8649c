-- The keywords of a check (TEST_RESU, TEST_FONCTION, TEST_TABLE), as code_aster's:
-- one of VALE_CALC / VALE_CALC_I / VALE_CALC_K (the value this program computed,
-- a non-regression check within TOLE_MACHINE) and, with REFERENCE, one of
-- VALE_REFE / _I / _K (within PRECISION). Each may list several values: the one
-- closest to the computed value is used. CRITERE (RELATIF or ABSOLU) applies to
-- both comparisons (the command's rule requires one VALE_CALC*). kinds lists the kinds of value: 'R' real, 'I' integer, 'K' text.
-- multi (TEST_RESU's RESU): TOLE_MACHINE and CRITERE take up to two values, the
-- second for finding INST in the result (the first for both when one is given).
local KIND = {
  R = { suffix = '', typ = 'R', word = 'Real' },
  I = { suffix = '_I', typ = 'I', word = 'Integer' },
  K = { suffix = '_K', typ = 'TXM', word = 'Text' },
}

function C_TEST_REFERENCE(kinds, multi)
  local calc, refe, refe_names = {}, {}, {}
  for i, kind in ipairs(kinds) do
    local k = KIND[kind]
    calc[i] = SIMP{ 'VALE_CALC' .. k.suffix, typ = k.typ, max = '**',
                    fr = k.word .. " value(s) computed by this program (non-regression; the closest is used)." }
    refe[i] = SIMP{ 'VALE_REFE' .. k.suffix, typ = k.typ, max = '**',
                    fr = k.word .. " reference value(s) (the closest is used)." }
    refe_names[i] = 'VALE_REFE' .. k.suffix
  end
  local tolerances
  if multi then
    tolerances = KEYWORDS{
      SIMP{ 'TOLE_MACHINE', typ = 'R', max = 2, val_min = 0.0,
            fr = "Tolerance of the comparison with VALE_CALC (default 1e-6); a second value: the precision finding INST." },
      SIMP{ 'CRITERE', typ = 'TXM', max = 2, into = {'RELATIF', 'ABSOLU'},
            fr = "Relative or absolute tolerances (default RELATIF); a second value: the criterion finding INST." },
    }
  else
    tolerances = KEYWORDS{
      SIMP{ 'TOLE_MACHINE', typ = 'R', defaut = 1.0e-6, val_min = 0.0,
            fr = "Tolerance of the comparison with VALE_CALC." },
      SIMP{ 'CRITERE', typ = 'TXM', defaut = 'RELATIF', into = {'RELATIF', 'ABSOLU'},
            fr = "Relative or absolute tolerances, for both comparisons." },
    }
  end
  return KEYWORDS{
    KEYWORDS(calc),
    SIMP{ 'VALE_ABS', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'},
          fr = "OUI: compare the absolute values (of the computed value and of the expected ones)." },
    tolerances,
    SIMP{ 'REFERENCE', typ = 'TXM', into = {'ANALYTIQUE', 'SOURCE_EXTERNE', 'AUTRE_ASTER', 'NON_DEFINI'},
          fr = "Origin of VALE_REFE; without it, only the non-regression check with VALE_CALC." },
    BLOC{ 'b_reference', condition = { REFERENCE = {'ANALYTIQUE', 'SOURCE_EXTERNE', 'AUTRE_ASTER', 'NON_DEFINI'} },
      regles = { UN_PARMI(table.unpack(refe_names)) },
      KEYWORDS(refe),
      SIMP{ 'PRECISION', typ = 'R', defaut = 1.0e-3, val_min = 0.0,
            fr = "Tolerance of the comparison with VALE_REFE." },
    },
    SIMP{ 'ORDRE_GRANDEUR', typ = 'R', val_min = 0.0,
          fr = "Only when VALE_CALC is 0: the magnitude scaling the absolute tolerance of the non-regression "
            .. "check (without it, that check is skipped)." },
    SIMP{ 'LEGENDE', typ = 'TXM', fr = "Label of the check in the output (default XXXX)." },
  }
end
