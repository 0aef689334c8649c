-- The keywords of a check (TEST_RESU, TEST_FONCTION, TEST_TABLE): the computed value,
-- its reference and the tolerances. Without REFERENCE (NON_REGRESSION) the value is
-- compared with VALE_CALC within TOLE_MACHINE; with a reference, also with VALE_REFE
-- within PRECISION. kinds lists the kinds of value checked: {'R'}, a real (VALE_CALC
-- mandatory); {'R', 'I', 'K'}, a real, an integer or a text (VALE_CALC, VALE_CALC_I,
-- VALE_CALC_K and their VALE_REFE: one of each, the command's rule says which).
local KIND = {
  R = { suffix = '', typ = 'R', word = 'Real' },
  I = { suffix = '_I', typ = 'I', word = 'Integer' },
  K = { suffix = '_K', typ = 'TXM', word = 'Text' },
}

function C_TEST_REFERENCE(kinds)
  local calc, refe, refe_names = {}, {}, {}
  if #kinds == 1 and kinds[1] == 'R' then
    calc[1] = SIMP{ 'VALE_CALC', statut = 'o', typ = 'R', fr = "Value computed by this program (non-regression)." }
    refe[1] = SIMP{ 'VALE_REFE', statut = 'o', typ = 'R', fr = "Reference value." }
  else
    for i, kind in ipairs(kinds) do
      local k = KIND[kind]
      calc[i] = SIMP{ 'VALE_CALC' .. k.suffix, typ = k.typ,
                      fr = k.word .. " value computed by this program (non-regression)." }
      refe[i] = SIMP{ 'VALE_REFE' .. k.suffix, typ = k.typ, fr = k.word .. " reference value." }
      refe_names[i] = 'VALE_REFE' .. k.suffix
    end
  end
  return KEYWORDS{
    KEYWORDS(calc),
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
      regles = #refe_names > 1 and { UN_PARMI(table.unpack(refe_names)) } or nil,
      KEYWORDS(refe),
      SIMP{ 'PRECISION', typ = 'R', defaut = 1.0e-3, val_min = 0.0,
            fr = "Tolerance of the comparison with VALE_REFE." },
    },
    SIMP{ 'ORDRE_GRANDEUR', typ = 'R', val_min = 0.0,
          fr = "Magnitude used for an absolute comparison when VALE_CALC is (nearly) zero." },
    SIMP{ 'LEGENDE', typ = 'TXM', defaut = 'XXXX', fr = "Label of the check in the output." },
  }
end
