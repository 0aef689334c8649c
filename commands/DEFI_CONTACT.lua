-- Every keyword here is honoured by src/commands/defi_contact.cpp. Where
-- code_aster offers values that aster-lite does not implement, `into` keeps the
-- implemented ones only, so that the validator rejects the others by name;
-- code_aster keywords of features aster-lite lacks are absent (the list is in
-- docs/manual.md, "Contact").

-- Adds the keywords shared by the DISCRETE and CONTINUE zones (pairing, normals,
-- exclusions) to a ZONE factor keyword.
local function pairing_keywords(zone)
  local common = {
    SIMP{ 'GROUP_MA_MAIT', statut = 'o', typ = 'grma',
          fr = "Master surface (edges in 2D); its normal (dy, -dx) must point towards the slave." },
    SIMP{ 'GROUP_MA_ESCL', statut = 'o', typ = 'grma', fr = "Slave surface (edges in 2D)." },
    SIMP{ 'NORMALE', typ = 'TXM', defaut = 'MAIT', into = {'MAIT'},
          fr = "Normal used for the contact: the master's (MAIT_ESCL and ESCL are not available)." },
    SIMP{ 'VECT_MAIT', typ = 'TXM', defaut = 'AUTO', into = {'AUTO'},
          fr = "Master normal computed from the geometry (FIXE and VECT_Y are not available)." },
    SIMP{ 'VECT_ESCL', typ = 'TXM', defaut = 'AUTO', into = {'AUTO'},
          fr = "Slave normal computed from the geometry (FIXE and VECT_Y are not available)." },
    SIMP{ 'TYPE_PROJECTION', typ = 'TXM', defaut = 'ORTHOGONALE', into = {'ORTHOGONALE'},
          fr = "Orthogonal projection of the slave points on the master (FIXE is not available)." },
    SIMP{ 'DIST_APPA', typ = 'R', defaut = -1.0,
          fr = "A slave point farther than this from its projection on the master is not paired (negative: no limit)." },
    SIMP{ 'TOLE_PROJ_EXT', typ = 'R', defaut = 0.5, val_min = 0.0,
          fr = "A point projecting past an end of the master by at most this (in the master cell's xi units, xi in [-1, 1]) is held at the end; farther, it is not paired." },
    SIMP{ 'SANS_GROUP_NO', typ = 'grno', max = '**',
          fr = "Slave nodes excluded from contact (e.g. also under Dirichlet conditions)." },
    SIMP{ 'SANS_NOEUD', typ = 'no', max = '**', fr = "Slave nodes excluded from contact, by name." },
    SIMP{ 'SANS_GROUP_MA', typ = 'grma', max = '**', fr = "Cells whose nodes are excluded from contact." },
    SIMP{ 'SANS_MAILLE', typ = 'ma', max = '**', fr = "Cells whose nodes are excluded from contact, by name." },
    SIMP{ 'RESOLUTION', typ = 'TXM', defaut = 'OUI', into = {'OUI'},
          fr = "Contact is solved (NON, the interpenetration check alone, is not available)." },
  }
  for _, k in ipairs(common) do zone[#zone + 1] = k end
  return zone
end

local function algo_reso_geom()
  return SIMP{ 'ALGO_RESO_GEOM', typ = 'TXM', defaut = 'NEWTON', into = {'NEWTON'},
    fr = "Geometric nonlinearity: the pairing is updated at every Newton iteration and linearized exactly (code_aster's POINT_FIXE loop, with REAC_GEOM, is not available)." }
end

return OPER{ nom = 'DEFI_CONTACT', sd_prod = 'char_contact', reentrant = 'n',
  fr = "Defines frictionless unilateral contact between master and slave boundaries.",
  SIMP{ 'MODELE', statut = 'o', typ = 'modele_sdaster', fr = "The model." },
  SIMP{ 'FORMULATION', typ = 'TXM', defaut = 'DISCRETE', into = {'DISCRETE', 'CONTINUE'},
        fr = "DISCRETE: node-to-segment with nodal multipliers and active set; CONTINUE: integrated, augmented Lagrangian (LAGS_C unknowns)." },
  SIMP{ 'FROTTEMENT', typ = 'TXM', defaut = 'SANS', into = {'SANS'}, fr = "Friction model (none)." },
  SIMP{ 'VERI_NORM', typ = 'TXM', defaut = 'OUI', into = {'OUI', 'NON'},
        fr = "OUI: stop when the normal of a master or slave cell points into the 2D cell it bounds (cells bounding no 2D cell, as a rigid master, are not checked)." },
  SIMP{ 'STOP_INTERP', typ = 'TXM', defaut = 'NON', into = {'NON'},
        fr = "Belongs to RESOLUTION='NON', which is not available." },
  SIMP{ 'INFO', typ = 'I', defaut = 1, into = {1, 2},
        fr = "2: prints CONT_NOEU (status, gap, pressure, force of each slave node) at each converged instant." },

  -- DISCRETE: a multiplier per slave node, active set.
  BLOC{ 'b_discrete', condition = { FORMULATION = 'DISCRETE' },
    algo_reso_geom(),
    SIMP{ 'LISSAGE', typ = 'TXM', defaut = 'NON', into = {'NON'},
          fr = "Master normals are not smoothed (OUI is available with FORMULATION='CONTINUE')." },
    SIMP{ 'STOP_SINGULIER', typ = 'TXM', defaut = 'OUI', into = {'OUI'},
          fr = "A singular system (a body held by contact alone before it touches, say) stops the computation." },
    pairing_keywords(FACT{ 'ZONE', statut = 'o', max = '**', fr = "A contact zone: a master/slave pair.",
      SIMP{ 'APPARIEMENT', typ = 'TXM', defaut = 'MAIT_ESCL', into = {'MAIT_ESCL'},
            fr = "Pairing: slave node to master segment (NODAL is not available)." },
      SIMP{ 'ALGO_CONT', typ = 'TXM', defaut = 'CONTRAINTE', into = {'CONTRAINTE', 'PENALISATION'},
            fr = "CONTRAINTE: active set with exact multipliers (no penetration); PENALISATION: penalty, the nodes penetrate by RN / E_N." },
      BLOC{ 'b_contrainte', condition = { ALGO_CONT = 'CONTRAINTE' },
        SIMP{ 'GLISSIERE', typ = 'TXM', defaut = 'NON', into = {'NON'},
              fr = "Unilateral contact (OUI, bilateral sliding, is not available)." },
      },
      BLOC{ 'b_penalisation', condition = { ALGO_CONT = 'PENALISATION' },
        SIMP{ 'E_N', statut = 'o', typ = 'R', val_min = 0.0,
              fr = "Penalty coefficient (> 0): contact pressure per unit penetration; a node carries it times its share of the slave length." },
      },
    }),
  },

  -- CONTINUE: integrated contact, generalized Newton.
  BLOC{ 'b_continue', condition = { FORMULATION = 'CONTINUE' },
    algo_reso_geom(),
    SIMP{ 'ALGO_RESO_CONT', typ = 'TXM', defaut = 'NEWTON', into = {'NEWTON'},
          fr = "Contact statuses inside Newton's loop, re-evaluated at every iteration (generalized Newton; POINT_FIXE is not available)." },
    SIMP{ 'LISSAGE', typ = 'TXM', defaut = 'NON', into = {'NON', 'OUI'},
          fr = "OUI: smoothed master normals, as code_aster's. The normal at a master node is the normalised mean of the normals, at that node, of the master cells around it (at most two), and the normal at a point of a master cell the normalised interpolation of its nodes' normals; the gap of a slave point is measured along it from its orthogonal projection, and the contact force acts along it (the tangent, exact, is then not symmetric). NON: each master cell's own normal." },
    pairing_keywords(FACT{ 'ZONE', statut = 'o', max = '**', fr = "A contact zone: a master/slave pair.",
      SIMP{ 'APPARIEMENT', typ = 'TXM', defaut = 'MAIT_ESCL', into = {'MAIT_ESCL'},
            fr = "Pairing: slave integration points projected on the master." },
      SIMP{ 'ALGO_CONT', typ = 'TXM', defaut = 'STANDARD', into = {'STANDARD', 'PENALISATION'},
            fr = "STANDARD: augmented Lagrangian (no penetration); PENALISATION: penalty, LAGS_C = COEF_PENA_CONT x gap where the gap is negative." },
      BLOC{ 'b_standard', condition = { ALGO_CONT = 'STANDARD' },
        SIMP{ 'COEF_CONT', typ = 'R', defaut = 100.0, val_min = 0.0, fr = "Augmentation coefficient (> 0), a pressure per unit gap used as given (as code_aster's): a point is in contact where LAGS_C + COEF_CONT x gap <= 0. Of the order of Young's modulus E of the bodies in contact, it forms the active set in fewer iterations." },
      },
      BLOC{ 'b_penalisation', condition = { ALGO_CONT = 'PENALISATION' },
        SIMP{ 'COEF_PENA_CONT', statut = 'o', typ = 'R', val_min = 0.0,
              fr = "Penalty coefficient (> 0): contact pressure per unit penetration." },
      },
      SIMP{ 'INTERPOL_LAGS_C', typ = 'TXM', defaut = 'QUADRATIQUE', into = {'QUADRATIQUE', 'LINEAIRE'},
            fr = "aster-lite's own: QUADRATIQUE, LAGS_C at every node of the slave cells, quadratic along a SEG3 (code_aster's; needs ORDRE_INT >= 3 with GAUSS); LINEAIRE, at the vertex nodes only, linear along each cell." },
      SIMP{ 'INTEGRATION', typ = 'TXM', defaut = 'GAUSS', into = {'GAUSS', 'AUTO'},
            fr = "Integration on the slave cells: Gauss points, or at the nodes (AUTO: trapezoid on a SEG2, Simpson on a SEG3); SIMPSON and NCOTES are not available." },
      BLOC{ 'b_gauss', condition = { INTEGRATION = 'GAUSS' },
        SIMP{ 'ORDRE_INT', typ = 'I', defaut = 3, val_min = 1, val_max = 6,
              fr = "Number of Gauss points per slave cell (the degree of the Legendre polynomial giving them)." },
      },
      SIMP{ 'CONTACT_INIT', typ = 'TXM', defaut = 'INTERPENETRE', into = {'INTERPENETRE', 'OUI', 'NON'},
            fr = "Statuses of the first Newton iteration: in contact where the points touch or interpenetrate, everywhere, or nowhere." },
      SIMP{ 'GLISSIERE', typ = 'TXM', defaut = 'NON', into = {'NON'},
            fr = "Unilateral contact (OUI, bilateral sliding, is not available)." },
    }),
  },
}
