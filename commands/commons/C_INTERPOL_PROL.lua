-- How a tabulated function is read between and beyond its points (DEFI_FONCTION,
-- RECU_FONCTION, CALC_FONC_INTERP).
function C_INTERPOL_PROL()
  return KEYWORDS{
    SIMP{ 'INTERPOL', typ = 'TXM', max = 2, defaut = 'LIN', into = {'LIN', 'LOG'},
          fr = "Interpolation of the abscissa and of the ordinate (one value: both)." },
    SIMP{ 'PROL_GAUCHE', typ = 'TXM', defaut = 'EXCLU', into = {'CONSTANT', 'LINEAIRE', 'EXCLU'},
          fr = "Extension left of the first abscissa (EXCLU: evaluating there is an error)." },
    SIMP{ 'PROL_DROITE', typ = 'TXM', defaut = 'EXCLU', into = {'CONSTANT', 'LINEAIRE', 'EXCLU'},
          fr = "Extension right of the last abscissa (EXCLU: evaluating there is an error)." },
  }
end
