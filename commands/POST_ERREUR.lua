-- aster-lite's own (after code_aster's POST_ERREUR): errors against an exact solution.
local FUNC = {'formule', 'fonction_sdaster', 'nappe_sdaster'}

return OPER{ nom = 'POST_ERREUR', sd_prod = 'table_sdaster', reentrant = 'n',
  fr = "L2 error of a computed field against an exact solution given by functions of X, Y. Returns a table: a row per group and a row TOTAL, with ERREUR (as OPTION says) and REFERENCE (the exact norm); the row TOTAL also has ERREUR RELATIVE (the norm of the difference over the exact norm, as code_aster's; absent when the exact norm is 0).",
  SIMP{ 'OPTION', statut = 'o', typ = 'TXM', into = {'DEPL_RELA', 'DEPL_ABSO', 'LAGR_RELA', 'LAGR_ABSO'},
        fr = "DEPL: displacement error over cells; LAGR: contact-pressure (LAGS_C) error over slave edges; RELA relative to the exact norm, ABSO absolute." },
  SIMP{ 'CHAM_GD', statut = 'o', typ = 'cham_no_sdaster', fr = "The computed nodal field (DEPL, with LAGS_C for LAGR)." },
  SIMP{ 'MODELE', statut = 'o', typ = 'modele_sdaster', fr = "The model." },
  SIMP{ 'GROUP_MA', statut = 'o', typ = 'grma', max = '**', fr = "Groups integrated over (cells for DEPL, edges for LAGR)." },
  BLOC{ 'b_depl', condition = { OPTION = {'DEPL_RELA', 'DEPL_ABSO'} },
    SIMP{ 'DX', statut = 'o', typ = FUNC, max = '**', fr = "Exact X displacement (one for all groups, or one per group)." },
    SIMP{ 'DY', statut = 'o', typ = FUNC, max = '**', fr = "Exact Y displacement (one for all groups, or one per group)." },
  },
  BLOC{ 'b_lagr', condition = { OPTION = {'LAGR_RELA', 'LAGR_ABSO'} },
    SIMP{ 'LAGS_C', statut = 'o', typ = FUNC, max = '**', fr = "Exact contact pressure (one for all groups, or one per group)." },
  },
}
