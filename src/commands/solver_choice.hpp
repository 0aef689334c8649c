// SOLVEUR (commands/commons/C_SOLVEUR.lua) of the mechanical operators: the linear solver
// of linalg::makeLinearSolver, its ordering and singularity test. code_aster's MUMPS and
// LDLT are solved by MULT_FRONT (an exact direct factorization as theirs), their orderings
// mapped onto MULT_FRONT's.
#pragma once
#include <string>

#include "lang/keywords.hpp"

namespace aster::lang {

struct SolverChoice {
  std::string method;  // a name of linalg::linearSolverMethods()
  std::string renum;   // an ordering that solver takes
  int nprec = 8;       // <= 0: only a zero pivot is singular (STOP_SINGULIER='NON')
};

SolverChoice readSolveur(const Keywords& solveur);

}  // namespace aster::lang
