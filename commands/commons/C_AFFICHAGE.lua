-- AFFICHAGE of the nonlinear operators: the layout of the convergence table.
function C_AFFICHAGE()
  return FACT{ 'AFFICHAGE', fr = "Layout of the convergence table (residual's node, times, a copy on a file unit, every PAS steps).",
    ignored = "it changes only the convergence table of the listing.",
    SIMP{ 'INFO_RESIDU', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'} },
    SIMP{ 'INFO_TEMPS', typ = 'TXM', defaut = 'NON', into = {'OUI', 'NON'} },
    SIMP{ 'UNITE', typ = 'I', val_min = 1 },
    SIMP{ 'PAS', typ = 'I', val_min = 1 },
  }
end
