-- The keywords that leave nodes out of a selection (code_aster's SANS_*):
-- groups or names of nodes, or the nodes of groups or names of cells.
function C_SANS()
  return KEYWORDS{
    SIMP{ 'SANS_GROUP_MA', typ = 'grma', max = '**', fr = "The nodes of the cells of these groups are left out." },
    SIMP{ 'SANS_MAILLE', typ = 'ma', max = '**', fr = "The nodes of these cells, by name, are left out." },
    SIMP{ 'SANS_GROUP_NO', typ = 'grno', max = '**', fr = "The nodes of these groups are left out." },
    SIMP{ 'SANS_NOEUD', typ = 'no', max = '**', fr = "These nodes, by name, are left out." },
  }
end
