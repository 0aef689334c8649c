// MECA_STATIQUE: linear elasticity in small strain at one or several instants,
// producing an evol_elas (the same fields per instant as STAT_NON_LINE's evol_noli).
#include <cmath>
#include <cstdio>
#include <optional>

#include "analysis/static_linear.hpp"
#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/mechanical_inputs.hpp"
#include "commands/model_concepts.hpp"
#include "commands/result_archive.hpp"
#include "commands/result_concepts.hpp"
#include "commands/solver_choice.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "lang/operators.hpp"

namespace aster::lang {
namespace {

// INST (one instant), or LIST_INST up to INST_FIN, or the instant 0.
std::vector<double> instantsOf(const Keywords& k) {
  if (k.has("INST")) {
    if (k.has("INST_FIN")) throw Error("INST_FIN goes with LIST_INST, not with INST");
    return {k.real("INST")};
  }
  if (!k.has("LIST_INST")) {
    if (k.has("INST_FIN")) throw Error("INST_FIN goes with LIST_INST, which is absent");
    return {0.0};
  }
  const auto& all = static_cast<RealListConcept&>(*k.conceptPtr("LIST_INST")).values;
  if (!k.has("INST_FIN")) return all;
  const double last = k.real("INST_FIN");
  const double eps = 1e-6 * std::max(1.0, std::fabs(last));
  std::vector<double> out;
  for (double t : all)
    if (t <= last + eps) out.push_back(t);
  if (out.empty())
    throw Error("INST_FIN=" + format::asterValue(last) + " is before the first instant of LIST_INST");
  return out;
}

ConceptPtr mecaStatique(const Keywords& k, Session& session, ConceptPtr) {
  auto model = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  analysis::MechanicalProblem problem;
  problem.model = model;
  auto matField = std::static_pointer_cast<MaterialFieldConcept>(k.conceptPtr("CHAM_MATER"));
  if (matField->mesh != model->meshPtr()) throw Error("CHAM_MATER was built on another mesh than MODELE's");
  problem.materials = matField->field;
  // Linear elasticity (ELAS of each cell's material, no COMPORTEMENT) in small strain.
  problem.kinematics.assign(model->cells().size(), mechanics::Kinematics::SmallStrain);
  std::vector<std::shared_ptr<LoadConcept>> keep;
  readExcit(k, session, model, problem, keep);
  const auto times = instantsOf(k);

  analysis::LinearSettings settings;
  const SolverChoice choice = readSolveur(k.factor("SOLVEUR").front());
  settings.method = choice.method;
  settings.renum = choice.renum;
  settings.nprec = choice.nprec;
  settings.mumps = choice.mumps;
  settings.gcpc = choice.gcpc;

  analysis::MechanicalSystem system(problem);
  analysis::StaticLinear solver(system, settings);
  auto result = std::make_shared<ResultConcept>(model, "evol_elas");
  result->materials = problem.materials;
  const bool stresses = k.text("OPTION") == "SIEF_ELGA";
  // Several instants go to disk as they are computed, as STAT_NON_LINE's do, so
  // that a failure at one leaves the earlier ones (one instant: nothing to keep).
  std::optional<ResultArchive> archive;
  if (times.size() > 1) {
    const std::string stem =
        session.uniqueOutputStem(session.assignedName.empty() ? "MECA_STATIQUE" : session.assignedName);
    archive.emplace(model->mesh(), session.outputFile(stem + ".pvd"), &session.files, "MECA_STATIQUE");
    Messages::info("MECA_STATIQUE: each instant is written to " + archive->path().string());
  }
  try {
    solver.run(times, [&](const analysis::ConvergedInstant& c) {
      ResultInstant inst = resultInstant(system, nullptr, c.time, *c.U, *c.internalForces, c.reactions, stresses);
      inst.index = static_cast<int>(result->instants.size()) + 1;  // code_aster numbers MECA_STATIQUE's from 1
      if (archive) archive->add(inst);  // an instant not on disk (full disk) is not in the result either
      result->instants.push_back(std::move(inst));
    });
  } catch (const Interrupted& e) {
    if (archive) throw Interrupted(e.what() + archive->storedNote("before it"));
    throw;
  } catch (const Error& e) {
    if (archive) throw Error(e.what() + archive->storedNote("before the failure"));
    throw;
  }

  const auto& st = solver.statistics();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "MECA_STATIQUE: %zu instant(s), %d factorization(s); %d unknowns; %.3f s (assembly %.3f s, "
                "linear solver %.3f s)",
                times.size(), st.factorizations, solver.unknownCount(), st.totalSeconds, st.assemblySeconds,
                st.solveSeconds);
  Messages::info(buf);
  if (k.integer("INFO") >= 2) {
    const auto& ls = solver.solverStatistics();
    char flops[48] = "flops not reported";
    if (ls.factorFlops >= 0) std::snprintf(flops, sizeof flops, "%.4g flops", ls.factorFlops);
    std::snprintf(buf, sizeof buf,
                  "MECA_STATIQUE: linear solver %s, RENUM='%s' (ordering used: %s), %lld nonzeros in the factors, %s",
                  settings.method.c_str(), settings.renum.c_str(),
                  ls.ordering.empty() ? "not reported" : ls.ordering.c_str(), ls.factorNonzeros, flops);
    Messages::info(buf);
    std::snprintf(buf, sizeof buf,
                  "MECA_STATIQUE: analysis %.3f s (%d), factorization %.3f s (%d), solves %.3f s (%d)",
                  ls.analyzeSeconds, ls.analyzeCount, ls.factorizeSeconds, ls.factorizeCount, ls.solveSeconds,
                  ls.solveCount);
    Messages::info(buf);
  }
  return result;
}

RegisterOperator reg("MECA_STATIQUE", mecaStatique);

}  // namespace
}  // namespace aster::lang
