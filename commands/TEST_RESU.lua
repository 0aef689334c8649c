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

-- Fields stored in a result (evol_noli).
local NOM_CHAM = {'DEPL', 'SIEF_ELGA', 'SIEF_NOEU', 'SIGM_NOEU', 'EPSI_ELGA', 'EPSI_NOEU',
                  'VARI_ELGA', 'FORC_NODA', 'REAC_NODA', 'CONT_NOEU', 'CONT_ELEM'}

local TYPE_TEST = {'SOMM_ABS', 'SOMM', 'MAX', 'MIN'}

return PROC{ nom = 'TEST_RESU',
  fr = "Checks values of fields and results against expected values; prints OK or NOOK for each.",
  regles = { AU_MOINS_UN('CHAM_NO', 'CHAM_ELEM', 'RESU') },
  with_check(FACT{ 'CHAM_NO', max = '**', fr = "Checks a nodal field: one value, or a sum or extreme over nodes.",
    regles = { UN_PARMI('NOEUD', 'GROUP_NO', 'TYPE_TEST'),
               PRESENT_PRESENT('NOEUD', 'NOM_CMP'), PRESENT_PRESENT('GROUP_NO', 'NOM_CMP') },
    SIMP{ 'CHAM_GD', statut = 'o', typ = 'cham_no_sdaster', fr = "The field." },
    SIMP{ 'NOEUD', typ = 'no', fr = "The node, by name." },
    SIMP{ 'GROUP_NO', typ = 'grno', fr = "A group holding one node." },
    SIMP{ 'NOM_CMP', typ = 'TXM', fr = "The component (with TYPE_TEST: restricts to it)." },
    SIMP{ 'TYPE_TEST', typ = 'TXM', into = TYPE_TEST,
          fr = "Over all nodes and components: sum of absolute values, sum, largest or smallest value." },
  }),
  with_check(FACT{ 'CHAM_ELEM', max = '**', fr = "Checks a field on cells: one value, or a sum or extreme.",
    regles = { UN_PARMI('GROUP_MA', 'TYPE_TEST'), EXCLUS('POINT', 'NOEUD', 'GROUP_NO'),
               PRESENT_PRESENT('GROUP_MA', 'NOM_CMP') },
    SIMP{ 'CHAM_GD', statut = 'o', typ = 'cham_elem', fr = "The field." },
    SIMP{ 'GROUP_MA', typ = 'grma', fr = "A group holding one cell." },
    SIMP{ 'POINT', typ = 'I', val_min = 1, fr = "Gauss point number in the cell (ELGA fields)." },
    SIMP{ 'SOUS_POINT', typ = 'I', val_min = 1, fr = "Sub-point number." },
    SIMP{ 'NOEUD', typ = 'no', fr = "Node of the cell (ELNO fields), by name." },
    SIMP{ 'GROUP_NO', typ = 'grno', fr = "A group holding the node of the cell (ELNO fields)." },
    SIMP{ 'NOM_CMP', typ = 'TXM', fr = "The component (with TYPE_TEST: restricts to it)." },
    SIMP{ 'TYPE_TEST', typ = 'TXM', into = TYPE_TEST,
          fr = "Over all points and components: sum of absolute values, sum, largest or smallest value." },
  }),
  with_check(FACT{ 'RESU', max = '**', fr = "Checks a field of a result at one instant, or a parameter of the result.",
    regles = { UN_PARMI('NUME_ORDRE', 'INST'), UN_PARMI('NOM_CHAM', 'PARA'),
               PRESENT_ABSENT('PARA', 'GROUP_MA', 'NOEUD', 'GROUP_NO', 'POINT', 'NOM_CMP', 'TYPE_TEST'),
               EXCLUS('NOEUD', 'GROUP_NO', 'POINT', 'TYPE_TEST') },
    SIMP{ 'RESULTAT', statut = 'o', typ = 'evol_noli', fr = "The result." },
    SIMP{ 'NUME_ORDRE', typ = 'I', val_min = 0, fr = "Storage index." },
    SIMP{ 'INST', typ = 'R', fr = "Instant." },
    SIMP{ 'NOM_CHAM', typ = 'TXM', into = NOM_CHAM, fr = "The field." },
    SIMP{ 'PARA', typ = 'TXM', fr = "A parameter stored with the result (ITER_GLOB, ...)." },
    SIMP{ 'NOM_CMP', typ = 'TXM', fr = "The component." },
    SIMP{ 'GROUP_MA', typ = 'grma', fr = "A group holding one cell (fields on cells)." },
    SIMP{ 'NOEUD', typ = 'no', fr = "The node, by name." },
    SIMP{ 'GROUP_NO', typ = 'grno', fr = "A group holding one node." },
    SIMP{ 'POINT', typ = 'I', val_min = 1, fr = "Gauss point number (ELGA fields)." },
    SIMP{ 'SOUS_POINT', typ = 'I', val_min = 1, fr = "Sub-point number." },
    SIMP{ 'TYPE_TEST', typ = 'TXM', into = TYPE_TEST,
          fr = "Over the whole field: sum of absolute values, sum, largest or smallest value." },
  }),
}
