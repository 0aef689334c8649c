#include "commands/solver_choice.hpp"

#include "core/error.hpp"

namespace aster::lang {

namespace {

// code_aster's MUMPS orderings that Debian's sequential MUMPS does not have.
void refuseMissingMumpsOrdering(const std::string& renum) {
  if (renum == "METIS")
    throw Error("SOLVEUR: RENUM='METIS' is not available with METHODE='MUMPS': Debian's sequential MUMPS is built "
                "without METIS; its nested dissections are 'SCOTCH' and 'PORD' (or 'AUTO', 'AMD', 'AMF', 'QAMD')");
  if (renum == "PARMETIS" || renum == "PTSCOTCH")
    throw Error("SOLVEUR: RENUM='" + renum + "' is a parallel ordering of MUMPS over MPI processes; aster-lite's "
                "MUMPS is sequential: use 'SCOTCH', 'PORD', 'AUTO', 'AMD', 'AMF' or 'QAMD'");
}

}  // namespace

SolverChoice readSolveur(const Keywords& solveur) {
  SolverChoice c;
  c.method = solveur.text("METHODE");
  // GCPC's RENUM (its preconditioner's) is ignored: MUMPS orders as it sees fit.
  c.renum = c.method == "GCPC" ? "AUTO" : solveur.text("RENUM");
  if (c.method == "MUMPS") {
    refuseMissingMumpsOrdering(c.renum);
    c.mumps.symmetry = solveur.text("TYPE_RESOL");
    c.mumps.pivotPercent = static_cast<int>(solveur.integer("PCENT_PIVOT"));
    c.mumps.preprocess = solveur.text("PRETRAITEMENTS") == "AUTO";
    c.mumps.refinement = solveur.text("POSTTRAITEMENTS");
    c.mumps.residualTolerance = solveur.real("RESI_RELA");
  } else if (c.method == "GCPC") {
    c.gcpc.preconditioner = solveur.text("PRE_COND");
    if (c.gcpc.preconditioner == "LDLT_INC")
      throw Error("SOLVEUR: PRE_COND='LDLT_INC' (code_aster's incomplete factorization) is not available with "
                  "METHODE='GCPC' in aster-lite; PRE_COND='LDLT_SP' (the default here) or 'LDLT_DP' precondition "
                  "with a complete factorization of an earlier matrix");
    c.gcpc.reacPrecond = static_cast<int>(solveur.integer("REAC_PRECOND"));
    c.gcpc.relativeResidual = solveur.real("RESI_RELA");
    c.gcpc.maxIterations = static_cast<int>(solveur.integer("NMAX_ITER"));
    c.gcpc.pivotPercent = static_cast<int>(solveur.integer("PCENT_PIVOT"));
  } else if (c.method == "LDLT") {
    c.method = "MULT_FRONT";
    c.renum = "AUTO";  // RCMK, a profile ordering: MULT_FRONT's fills less
  } else if (c.method == "MULT_FRONT" && (c.renum == "MD" || c.renum == "MDA")) {
    c.renum = "AMD";
  }
  c.nprec = solveur.text("STOP_SINGULIER") == "NON" ? 0 : static_cast<int>(solveur.integer("NPREC"));
  return c;
}

}  // namespace aster::lang
