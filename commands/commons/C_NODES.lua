-- Nodes designated by cells or by nodes, by group or by name: the keywords a
-- Dirichlet condition or a linear relation selects its nodes with (the
-- command's rule says which are required, C_SANS takes some away).
function C_NODES()
  return KEYWORDS{
    SIMP{ 'GROUP_MA', typ = 'grma', max = '**', fr = "Nodes of the cells of these groups." },
    SIMP{ 'MAILLE', typ = 'ma', max = '**', fr = "Nodes of these cells, by name." },
    SIMP{ 'GROUP_NO', typ = 'grno', max = '**', fr = "Nodes of these groups." },
    SIMP{ 'NOEUD', typ = 'no', max = '**', fr = "These nodes, by name." },
  }
end
