// STAT_NON_LINE: quasi-static nonlinear analysis (Newton) over a list of instants.
// The operator reads (the problem, the driver's settings, the initial state, the
// instants), builds (the system, the contact terms, the driver with its convergence
// table), runs, storing each converged instant as it comes, and reports.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "commands/archiving.hpp"
#include "commands/contact_concept.hpp"
#include "core/number_format.hpp"
#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/list_inst_concept.hpp"
#include "commands/mechanical_inputs.hpp"
#include "commands/model_concepts.hpp"
#include "commands/result_archive.hpp"
#include "commands/result_concepts.hpp"
#include "commands/solver_choice.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "analysis/convergence_table.hpp"
#include "analysis/static_nonlinear.hpp"

namespace aster::lang {
namespace {

// The instants of INCREMENT between INST_INIT (or NUME_INST_INIT; by default
// `initialTime` when ETAT_INIT gives one, else the first of the list) and INST_FIN
// (or NUME_INST_FIN), looked up with PRECISION (relative); a DEFI_LIST_INST gives `settings`
// its step cutting.
std::vector<double> instantsOf(const Keywords& inc, analysis::NewtonSettings& settings, const double* initialTime) {
  const ConceptPtr list = inc.conceptPtr("LIST_INST");
  std::vector<double> all;
  if (auto* li = dynamic_cast<ListInstConcept*>(list.get())) {
    all = li->times;
    settings.subdPas = li->subdPas;
    settings.subdNiveau = li->subdNiveau;
    settings.subdAuto = li->subdAuto;
    settings.subdPasMini = li->subdPasMini;
  } else {
    all = static_cast<RealListConcept&>(*list).values;
  }
  if (all.size() < 2) throw Error("INCREMENT/LIST_INST must hold at least two instants");
  const double eps = inc.real("PRECISION") * std::max(1.0, std::fabs(all.back() - all.front()));
  const long long last = static_cast<long long>(all.size()) - 1;
  auto byIndex = [&](const char* key) {
    const long long i = inc.integer(key);
    if (i > last)
      throw Error(std::string("INCREMENT/") + key + "=" + std::to_string(i) + ": LIST_INST has indices 0 to " +
                  std::to_string(last));
    return all[static_cast<std::size_t>(i)];
  };
  const double t0 = inc.has("NUME_INST_INIT") ? byIndex("NUME_INST_INIT")
                    : inc.has("INST_INIT")    ? inc.real("INST_INIT")
                    : initialTime             ? *initialTime
                                              : all.front();
  const double t1 = inc.has("NUME_INST_FIN") ? byIndex("NUME_INST_FIN")
                    : inc.has("INST_FIN")    ? inc.real("INST_FIN")
                                             : all.back();
  std::vector<double> out;
  for (double t : all)
    if (t >= t0 - eps && t <= t1 + eps) out.push_back(t);
  if (out.empty() || std::fabs(out.front() - t0) > eps)
    throw Error(std::string(inc.has("INST_INIT") ? "INCREMENT/INST_INIT=" : "the initial instant ") +
                format::asterValue(t0) + (!inc.has("INST_INIT") && initialTime ? " (ETAT_INIT's)" : "") +
                " is not an instant of LIST_INST");
  if (out.size() < 2) throw Error("INCREMENT: no instant to compute between INST_INIT and INST_FIN");
  return out;
}

// COMPORTEMENT, EXCIT: the problem (model, materials, behaviour per cell, loads). `keep`
// holds the loads the problem points to.
analysis::MechanicalProblem readProblem(const Keywords& k, Session& session,
                                        std::vector<std::shared_ptr<LoadConcept>>& keep) {
  auto model = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  const auto& mesh = model->mesh();
  analysis::MechanicalProblem problem;
  problem.model = model;
  auto matField = std::static_pointer_cast<MaterialFieldConcept>(k.conceptPtr("CHAM_MATER"));
  if (matField->mesh != model->meshPtr())
    throw Error("CHAM_MATER was built on another mesh than MODELE's");
  problem.materials = matField->field;

  // Behaviour: PETIT everywhere unless COMPORTEMENT says otherwise.
  std::vector<mechanics::Kinematics> byCell(mesh.cellCount(), mechanics::Kinematics::SmallStrain);
  for (const auto& occ : k.factor("COMPORTEMENT")) {
    const auto kin = mechanics::kinematicsFromName(occ.text("DEFORMATION"));
    std::vector<int> cells = occ.has("GROUP_MA") || occ.has("MAILLE") ? selectCells(mesh, occ) : model->cells();
    for (int c : cells) byCell[c] = kin;
  }
  for (int c : model->cells()) problem.kinematics.push_back(byCell[c]);

  readExcit(k, session, model, problem, keep);
  return problem;
}

// NEWTON, CONVERGENCE, SOLVEUR: the driver's settings (the step cutting comes with the instants).
analysis::NewtonSettings readNewtonSettings(const Keywords& k) {
  analysis::NewtonSettings settings;
  const auto& newton = k.factor("NEWTON").front();
  const std::string matrice = newton.text("MATRICE");
  settings.elasticMatrix = matrice == "ELASTIQUE";
  const std::string prediction = newton.has("PREDICTION") ? newton.text("PREDICTION") : matrice;
  settings.prediction = prediction == "ELASTIQUE"   ? analysis::Prediction::Elastic
                        : prediction == "EXTRAPOLE" ? analysis::Prediction::Extrapolated
                                                    : analysis::Prediction::Tangent;
  settings.reacIter = static_cast<int>(newton.integer("REAC_ITER"));
  settings.reacIncr = static_cast<int>(newton.integer("REAC_INCR"));
  settings.symmetrize = newton.text("MATR_RIGI_SYME") == "OUI";
  const auto& conv = k.factor("CONVERGENCE").front();
  // RESI_GLOB_RELA (1e-6 by default, when RESI_GLOB_MAXI is absent) and/or RESI_GLOB_MAXI.
  settings.useRela = conv.has("RESI_GLOB_RELA");
  if (settings.useRela) settings.resiGlobRela = conv.real("RESI_GLOB_RELA");
  settings.useMaxi = conv.has("RESI_GLOB_MAXI");
  if (settings.useMaxi) settings.resiGlobMaxi = conv.real("RESI_GLOB_MAXI");
  settings.iterGlobMaxi = static_cast<int>(conv.integer("ITER_GLOB_MAXI"));
  settings.arret = conv.text("ARRET") == "OUI";
  const SolverChoice choice = readSolveur(k.factor("SOLVEUR").front());
  settings.method = choice.method;
  settings.renum = choice.renum;
  settings.nprec = choice.nprec;
  if (k.has("RECH_LINEAIRE")) {
    const auto& rl = k.factor("RECH_LINEAIRE").front();
    auto& ls = settings.lineSearchSettings;
    settings.lineSearch = true;
    ls.method = rl.text("METHODE") == "MIXTE" ? analysis::LineSearchSettings::Method::Mixte
                                              : analysis::LineSearchSettings::Method::Corde;
    ls.resiLineRela = rl.real("RESI_LINE_RELA");
    ls.iterLineMaxi = static_cast<int>(rl.integer("ITER_LINE_MAXI"));
    ls.rhoMin = rl.real("RHO_MIN");
    ls.rhoMax = rl.real("RHO_MAX");
    ls.rhoExcl = rl.real("RHO_EXCL");
    if (!(ls.rhoMin < ls.rhoMax))
      throw Error("RECH_LINEAIRE: RHO_MIN (" + format::asterValue(ls.rhoMin) + ") must be less than RHO_MAX (" +
                  format::asterValue(ls.rhoMax) + ")");
  }
  return settings;
}

// ETAT_INIT: the state to start from, an instant of an EVOL_NOLI or a DEPL field (or neither).
struct InitialState {
  const ResultInstant* instant = nullptr;  // EVOL_NOLI's (it gives the initial instant too)
  const NodalFieldConcept* field = nullptr;  // DEPL's
};

InitialState readInitialState(const Keywords& k, Session& session, const model::Model& model, const ConceptPtr& reuse) {
  InitialState state;
  if (k.has("ETAT_INIT")) {
    const auto& init = k.factor("ETAT_INIT").front();
    if (init.has("EVOL_NOLI")) {
      const auto& prev = static_cast<ResultConcept&>(*init.conceptPtr("EVOL_NOLI"));
      if (prev.model->meshPtr() != model.meshPtr())
        throw Error("ETAT_INIT/EVOL_NOLI was computed on another mesh than MODELE's");
      try {
        state.instant = &instantOf(prev, init);
      } catch (const Error& e) {
        throw Error("ETAT_INIT: " + std::string(e.what()));
      }
    } else {
      state.field = dynamic_cast<const NodalFieldConcept*>(init.conceptPtr("DEPL").get());
      if (!state.field || isFunctionField(*state.field))
        throw Error("ETAT_INIT/DEPL: " + session.nameOf(*init.conceptPtr("DEPL")) + " is not a field of real nodal values");
      if (state.field->mesh != model.meshPtr())
        throw Error("ETAT_INIT/DEPL: the field is defined on another mesh than MODELE's");
    }
  } else if (reuse) {
    throw Error("reuse=: STAT_NON_LINE continues a result from a state; give ETAT_INIT = {EVOL_NOLI = " +
                session.nameOf(*reuse) + "} (its last instant, or INST / NUME_ORDRE)");
  }
  return state;
}

// The displacement unknowns of U from the initial state's DEPL (U stays zero without one).
void setInitialUnknowns(const InitialState& state, const analysis::MechanicalSystem& system, Eigen::VectorXd& U) {
  if (!state.instant && !state.field) return;
  const auto& depl = state.instant ? ResultConcept::nodalField(*state.instant, "DEPL") : state.field->field;
  const int nc = static_cast<int>(depl.components.size());
  const int cx = componentIndex(depl, "DX", "ETAT_INIT/DEPL"), cy = componentIndex(depl, "DY", "ETAT_INIT/DEPL");
  for (int n = 0; n < system.model().mesh().nodeCount(); ++n)
    for (int c = 0; c < 2; ++c)
      if (system.dof(n, c) >= 0) U(system.dof(n, c)) = depl.values[n * nc + (c == 0 ? cx : cy)];
}

// The run's figures; INFO >= 2 adds the linear solver's.
void reportStatistics(const analysis::StaticNonlinear& newtonSolver, const analysis::NewtonSettings& settings,
                      std::size_t instants, long long info) {
  const auto& st = newtonSolver.statistics();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "STAT_NON_LINE: %zu instants, %d Newton iterations, %d factorizations, %d step cuts; "
                "%d unknowns; %.3f s (assembly %.3f s, linear solver %.3f s)",
                instants, st.iterations, st.factorizations, st.cuts, newtonSolver.unknownCount(),
                st.totalSeconds, st.assemblySeconds, st.solveSeconds);
  std::string line = buf;
  if (settings.lineSearch)
    line += "; line search: " + std::to_string(st.lineSearchTrials) + " residuals evaluated";
  Messages::info(line);
  if (info >= 2) {
    const auto& ls = newtonSolver.solverStatistics();
    char flops[48] = "flops not reported";
    if (ls.factorFlops >= 0) std::snprintf(flops, sizeof flops, "%.4g flops", ls.factorFlops);
    std::snprintf(buf, sizeof buf,
                  "STAT_NON_LINE: linear solver %s, RENUM='%s' (ordering used: %s), %d factorizations "
                  "(%.3f s), %lld nonzeros in the last factors, %s",
                  settings.method.c_str(), settings.renum.c_str(), ls.ordering.empty() ? "not reported" : ls.ordering.c_str(),
                  ls.factorizeCount, ls.factorizeSeconds, ls.factorNonzeros, flops);
    Messages::info(buf);
  }
}

ConceptPtr statNonLine(const Keywords& k, Session& session, ConceptPtr reuse) {
  // Read: the problem, the driver's settings, the initial state, the instants.
  std::vector<std::shared_ptr<LoadConcept>> keep;
  analysis::MechanicalProblem problem = readProblem(k, session, keep);
  const auto model = static_cast<ModelConcept&>(*k.conceptPtr("MODELE")).model;
  const auto& mesh = model->mesh();
  analysis::NewtonSettings settings = readNewtonSettings(k);
  const InitialState initial = readInitialState(k, session, *model, reuse);
  const double initialTime = initial.instant ? initial.instant->time : 0.0;
  const auto times = instantsOf(k.factor("INCREMENT").front(), settings, initial.instant ? &initialTime : nullptr);

  // Build: the system, the contact terms, the driver and its convergence table.
  analysis::MechanicalSystem system(problem);
  std::unique_ptr<analysis::AdditionalTerms> terms;
  if (const auto contact = k.concept<ContactConcept>("CONTACT")) {
    if (model->axisymmetric())
      throw Error("CONTACT: MODELE is axisymmetric (MODELISATION='AXIS'); the contact of DEFI_CONTACT is plane (not "
                  "weighted by the radius): contact is available in D_PLAN and C_PLAN only");
    terms = analysis::makeContactTerms(system, contact->zones, contact->settings);
  }
  analysis::StaticNonlinear newtonSolver(system, terms.get(), settings);
  analysis::ConvergenceTable table(terms != nullptr, settings.lineSearch);
  if (k.integer("INFO") >= 1) newtonSolver.addObserver(table);

  const Archiving archiving(k.factor("ARCHIVAGE").front(), times);

  // The result: continued (reuse) from the initial instant, or new with the initial state.
  std::shared_ptr<ResultConcept> result =
      reuse ? std::static_pointer_cast<ResultConcept>(reuse) : std::make_shared<ResultConcept>(model);
  result->materials = problem.materials;
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newtonSolver.unknownCount());
  setInitialUnknowns(initial, system, U);
  if (reuse) {
    // A restart from an earlier instant replaces what the result held after it.
    const double eps = 1e-6 * std::max(1.0, std::fabs(times.front()));
    auto& kept = result->instants;
    kept.erase(std::remove_if(kept.begin(), kept.end(), [&](const ResultInstant& i) { return i.time > times.front() + eps; }),
               kept.end());
  } else {
    // NUME_ORDRE 0: the initial state, with its internal forces, stresses and reactions
    // (the internal forces less the loads; zero unless ETAT_INIT or a load at the first instant).
    // The state is given, not solved for: as code_aster, the analysis never needs the loads
    // at the initial instant (a FONC_MULT may start after it, PROL_GAUCHE='EXCLU'); when they
    // are not defined there, REAC_NODA is absent at NUME_ORDRE 0 (code_aster's CALC_CHAMP
    // could not compute it either).
    Eigen::VectorXd fint, fext;
    system.internalForces(U.head(system.dofCount()), fint);
    std::optional<Eigen::VectorXd> reactions;
    try {
      system.evaluate(U.head(system.dofCount()), times.front(), fint, fext, nullptr, nullptr);
      reactions = fint - fext;
    } catch (const Error& e) {
      Messages::info("STAT_NON_LINE: no REAC_NODA at the initial instant " + format::asterValue(times.front()) +
                     ": the loads are not defined there (" + e.what() + ")");
    }
    result->instants.push_back(resultInstant(system, terms.get(), times.front(), U, fint,
                                             reactions ? &*reactions : nullptr, true, false));
    archiving.strip(result->instants.back());
  }

  // Every instant goes to disk as soon as it is in the result.
  const std::string stem = session.uniqueOutputStem(session.assignedName.empty() ? "STAT_NON_LINE" : session.assignedName);
  ResultArchive archive(mesh, session.outputFile(stem + ".pvd"), &session.files);
  try {
    for (const auto& inst : result->instants) archive.add(inst);
  } catch (const Error& e) {
    throw Error(e.what() + archive.storedNote("before the failure"));
  }
  Messages::info("STAT_NON_LINE: each converged instant is written to " + archive.path().string());

  // Run: each converged instant ARCHIVAGE keeps is stored as it comes. The last converged
  // one is stored too when a later one fails (or Ctrl-C), as code_aster does: it is kept
  // aside until the next converges.
  std::size_t step = 0;
  std::optional<ResultInstant> pending;
  auto add = [&](ResultInstant inst) {
    inst.index = static_cast<int>(result->instants.size());
    archive.add(inst);  // an instant that is not on disk (full disk) is not in the result either
    result->instants.push_back(std::move(inst));
  };
  auto store = [&](const analysis::ConvergedInstant& c) {
    ResultInstant inst = resultInstant(system, terms.get(), c.time, *c.U, *c.internalForces, c.reactions);
    archiving.strip(inst);
    inst.newtonIterations = c.iterations;
    pending.reset();
    if (archiving.stored(++step)) add(std::move(inst));
    else pending = std::move(inst);
  };
  auto storePending = [&] {
    if (!pending) return;
    ResultInstant inst = std::move(*pending);
    pending.reset();
    try {
      add(std::move(inst));
    } catch (const Error&) {
      // The failure being reported matters more than this instant.
    }
  };
  try {
    newtonSolver.run(U, times, store);
  } catch (const Interrupted& e) {
    storePending();
    throw Interrupted(e.what() + archive.storedNote("before it"));
  } catch (const Error& e) {
    // The converged instants stay in the result; the study stops here.
    storePending();
    throw Error(e.what() + archive.storedNote("before the failure"));
  }
  reportStatistics(newtonSolver, settings, times.size() - 1, k.integer("INFO"));
  return result;
}

RegisterOperator reg("STAT_NON_LINE", statNonLine);

}  // namespace
}  // namespace aster::lang
