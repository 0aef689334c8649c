return PROC{ nom = 'PRE_GMSH',
  fr = "Converts a gmsh mesh (MSH 1, or MSH 2 ASCII) into an ASTER mesh (.mail) for LIRE_MAILLAGE{FORMAT='ASTER'}, as code_aster's PRE_GMSH: nodes N<number>, cells M<number>, groups of cells GM<physical tag> (with a group of nodes GM<tag> for a group of one POI1).",
  SIMP{ 'UNITE_GMSH', typ = 'I', defaut = 19, val_min = 1,
        fr = "Logical unit of the gmsh file (see DEFI_FICHIER or the -u option)." },
  SIMP{ 'UNITE_MAILLAGE', typ = 'I', defaut = 20, val_min = 1,
        fr = "Logical unit the ASTER mesh is written on: the file bound to it, else <output>/<study>.mail, which the unit is then bound to for LIRE_MAILLAGE." },
  SIMP{ 'INFO', typ = 'I', defaut = 1, into = {1, 2}, fr = "Verbosity: 2 prints the mesh summary." },
}
