-- A first study from a gmsh mesh (docs/manual.md): a square plate with a circular
-- hole under tension, in plane stress. The quarter x >= 0, y >= 0 of the plate is
-- meshed by gmsh from plaque_trou.geo (gmsh -2 plaque_trou.geo writes plaque_trou.msh,
-- which LIRE_MAILLAGE reads on its unit 19). Lengths in mm, stresses in MPa.
DEBUT()

-- The mesh: gmsh's physical groups become groups of cells and of nodes.
MAIL = LIRE_MAILLAGE{FORMAT = 'GMSH', UNITE = 19}

MODELE = AFFE_MODELE{MAILLAGE = MAIL,
                     AFFE = {TOUT = 'OUI', PHENOMENE = 'MECANIQUE', MODELISATION = 'C_PLAN'}}

ACIER = DEFI_MATERIAU{ELAS = {E = 210000.0, NU = 0.3}}
CHMAT = AFFE_MATERIAU{MAILLAGE = MAIL, AFFE = {TOUT = 'OUI', MATER = ACIER}}

-- Symmetry on the two cut edges, a tension of 100 MPa on the right edge.
CHAR = AFFE_CHAR_MECA{MODELE = MODELE,
                      DDL_IMPO = {{GROUP_MA = 'BAS', DY = 0.0},
                                  {GROUP_MA = 'GAUCHE', DX = 0.0}},
                      FORCE_CONTOUR = {GROUP_MA = 'DROITE', FX = 100.0}}

RESU = MECA_STATIQUE{MODELE = MODELE, CHAM_MATER = CHMAT, EXCIT = {CHARGE = CHAR}}

-- Stresses at the nodes, and the von Mises equivalent stress.
RESU = CALC_CHAMP{reuse = RESU, RESULTAT = RESU,
                  CONTRAINTE = {'SIGM_ELNO', 'SIGM_NOEU'}, CRITERES = {'SIEQ_ELNO', 'SIEQ_NOEU'}}

-- At the top of the hole (A), SIXX is 3 times the remote stress in an infinite plate
-- (Kirsch); in this plate, 20 hole radii wide, it is about 0.65 % more (finer meshes).
TEST_RESU{RESU = {
  {RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'A', NOM_CMP = 'SIXX',
   VALE_CALC = 301.105319971, VALE_REFE = 300.0, REFERENCE = 'ANALYTIQUE', PRECISION = 0.01},
  -- At B, the hoop stress is minus the remote stress.
  {RESULTAT = RESU, NUME_ORDRE = 1, NOM_CHAM = 'SIGM_NOEU', GROUP_NO = 'B', NOM_CMP = 'SIYY',
   VALE_CALC = -100.746812215, VALE_REFE = -100.0, REFERENCE = 'ANALYTIQUE', PRECISION = 0.03},
}}

-- For ParaView (plaque_trou/plaque_trou.pvd) and for MED readers (plaque_trou/plaque_trou.med).
IMPR_RESU{FORMAT = 'VTK', RESU = {RESULTAT = RESU}}
IMPR_RESU{FORMAT = 'MED', RESU = {RESULTAT = RESU}}

FIN()
