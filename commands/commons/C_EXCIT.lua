-- The loads of the mechanical operators (STAT_NON_LINE, MECA_STATIQUE): each its
-- own TYPE_CHARGE keyword, since only STAT_NON_LINE has follower loads.
function C_EXCIT(typeCharge)
  return KEYWORDS{
    FACT{ 'EXCIT', max = '**', fr = "A load and its multiplier in time.",
      SIMP{ 'CHARGE', statut = 'o', typ = {'char_meca', 'char_cine_meca'},
            fr = "The load (AFFE_CHAR_MECA, AFFE_CHAR_MECA_F or AFFE_CHAR_CINE)." },
      SIMP{ 'FONC_MULT', typ = {'fonction_sdaster', 'formule', 'nappe_sdaster'},
            fr = "Multiplier, a function of INST (default: 1)." },
      typeCharge,
    },
  }
end
