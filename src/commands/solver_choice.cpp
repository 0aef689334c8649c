#include "commands/solver_choice.hpp"

namespace aster::lang {

namespace {

// MUMPS's orderings: the minimum degree family is AMD, the nested dissections METIS.
std::string mumpsOrdering(const std::string& renum) {
  if (renum == "AUTO") return "AUTO";
  if (renum == "AMD" || renum == "AMF" || renum == "QAMD") return "AMD";
  return "METIS";  // METIS, PORD, SCOTCH, PARMETIS, PTSCOTCH
}

}  // namespace

SolverChoice readSolveur(const Keywords& solveur) {
  SolverChoice c;
  c.method = solveur.text("METHODE");
  c.renum = solveur.text("RENUM");
  if (c.method == "MUMPS") {
    c.method = "MULT_FRONT";
    c.renum = mumpsOrdering(c.renum);
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
