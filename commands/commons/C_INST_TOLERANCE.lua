-- How an instant given by INST is looked up among the stored ones.
function C_INST_TOLERANCE()
  return KEYWORDS{
    SIMP{ 'CRITERE', typ = 'TXM', defaut = 'RELATIF', into = {'RELATIF', 'ABSOLU'}, fr = "Kind of tolerance on INST." },
    SIMP{ 'PRECISION', typ = 'R', defaut = 1.0e-6, val_min = 0.0, fr = "Tolerance when looking up INST." },
  }
end
