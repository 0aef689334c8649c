-- The MECA_IMPO keyword of AFFE_CHAR_CINE (values: reals) and AFFE_CHAR_CINE_F
-- (values: functions of space and INST): V is the type, or list of types, of the values.
function C_MECA_IMPO(V)
  return KEYWORDS{
    SIMP{ 'MODELE', statut = 'o', typ = 'modele_sdaster', fr = "The model." },
    FACT{ 'MECA_IMPO', statut = 'o', max = '**', fr = "Imposed displacement values.",
      regles = { UN_PARMI('TOUT', 'GROUP_MA', 'MAILLE', 'GROUP_NO', 'NOEUD'), AU_MOINS_UN('DX', 'DY') },
      SIMP{ 'TOUT', typ = 'TXM', into = {'OUI'}, fr = "Every node of the model." },
      C_NODES(),
      SIMP{ 'DX', typ = V, fr = "Imposed displacement along X." },
      SIMP{ 'DY', typ = V, fr = "Imposed displacement along Y." },
    },
    SIMP{ 'INFO', typ = 'I', defaut = 1, into = {1, 2}, fr = "Verbosity.",
        ignored = "a listing option; this command prints nothing more with INFO=2." },
  }
end
