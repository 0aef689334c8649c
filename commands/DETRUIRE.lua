-- Every concept type of aster-lite.
local CONCEPTS = {'maillage_sdaster', 'modele_sdaster', 'mater_sdaster', 'cham_mater', 'char_meca',
                  'char_cine_meca', 'char_contact', 'fonction_sdaster', 'nappe_sdaster', 'formule',
                  'listr8_sdaster', 'list_inst', 'evol_noli', 'evol_elas', 'cham_no_sdaster', 'cham_elem',
                  'table_sdaster', 'solu_manu'}

return PROC{ nom = 'DETRUIRE',
  fr = "Destroys concepts, so that their names can be reused and their memory freed.",
  regles = { UN_PARMI('CONCEPT', 'NOM') },
  FACT{ 'CONCEPT', max = '**', fr = "Older syntax: the concepts to destroy.",
    SIMP{ 'NOM', statut = 'o', typ = CONCEPTS, max = '**', fr = "Concepts to destroy." },
  },
  SIMP{ 'NOM', typ = CONCEPTS, max = '**', fr = "Concepts to destroy." },
  SIMP{ 'INFO', typ = 'I', defaut = 1, into = {1, 2}, fr = "Verbosity." },
}
