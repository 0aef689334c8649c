// SOLVEUR (commands/commons/C_SOLVEUR.lua) of the mechanical operators: the linear solver
// of linalg::makeLinearSolver, its ordering and singularity test, and MUMPS's controls.
// code_aster's LDLT is solved by MULT_FRONT (an exact direct factorization as its own).
#pragma once
#include <string>

#include "lang/keywords.hpp"
#include "linalg/gcpc_solver.hpp"
#include "linalg/mumps_solver.hpp"

namespace aster::lang {

struct SolverChoice {
  std::string method;  // a name of linalg::linearSolverMethods()
  std::string renum;   // an ordering that solver takes
  int nprec = 8;       // <= 0: only a zero pivot is singular (STOP_SINGULIER='NON')
  linalg::MumpsOptions mumps;  // METHODE='MUMPS': TYPE_RESOL, PCENT_PIVOT, PRETRAITEMENTS, POSTTRAITEMENTS, RESI_RELA
  linalg::GcpcOptions gcpc;    // METHODE='GCPC': PRE_COND, REAC_PRECOND, RESI_RELA, NMAX_ITER, PCENT_PIVOT
};

SolverChoice readSolveur(const Keywords& solveur);

}  // namespace aster::lang
