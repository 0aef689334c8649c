// STAT_NON_LINE: quasi-static nonlinear analysis (Newton) over a list of instants.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "commands/contact_concept.hpp"
#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/list_inst_concept.hpp"
#include "commands/model_concepts.hpp"
#include "commands/result_archive.hpp"
#include "commands/result_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/messages.hpp"
#include "lang/operators.hpp"
#include "analysis/static_nonlinear.hpp"

namespace aster::lang {
namespace {

mechanics::Kinematics kinematicsFromName(const std::string& d) {
  if (d == "PETIT") return mechanics::Kinematics::SmallStrain;
  if (d == "GROT_GDEP" || d == "GREEN_LAGRANGE") return mechanics::Kinematics::TotalLagrangianSVK;
  throw Error("DEFORMATION='" + d + "' is not available (PETIT, GROT_GDEP, GREEN_LAGRANGE)");
}

// The instants of INCREMENT between INST_INIT (or NUME_INST_INIT; by default
// `initialTime` when ETAT_INIT gives one, else the first of the list) and INST_FIN
// (or NUME_INST_FIN), looked up with PRECISION (relative).
std::vector<double> instantsOf(const Keywords& inc, int& subdPas, int& subdNiveau, const double* initialTime) {
  const ConceptPtr list = inc.conceptPtr("LIST_INST");
  std::vector<double> all;
  if (auto* li = dynamic_cast<ListInstConcept*>(list.get())) {
    all = li->times;
    subdPas = li->subdPas;
    subdNiveau = li->subdNiveau;
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
                post::formatNumber(t0) + (!inc.has("INST_INIT") && initialTime ? " (ETAT_INIT's)" : "") +
                " is not an instant of LIST_INST");
  if (out.size() < 2) throw Error("INCREMENT: no instant to compute between INST_INIT and INST_FIN");
  return out;
}

ConceptPtr statNonLine(const Keywords& k, Session& session, ConceptPtr reuse) {
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
    const auto kin = kinematicsFromName(occ.text("DEFORMATION"));
    std::vector<int> cells = occ.has("GROUP_MA") ? selectCells(mesh, occ) : model->cells();
    for (int c : cells) byCell[c] = kin;
  }
  for (int c : model->cells()) problem.kinematics.push_back(byCell[c]);

  std::vector<std::shared_ptr<LoadConcept>> keep;
  for (const auto& occ : k.factor("EXCIT")) {
    auto load = std::static_pointer_cast<LoadConcept>(occ.conceptPtr("CHARGE"));
    if (load->model != model) throw Error(occ.path + ": CHARGE was defined on another MODELE");
    analysis::AppliedLoad applied;
    applied.load = &load->load;
    applied.follower = occ.text("TYPE_CHARGE") == "SUIV";
    if (applied.follower) {
      // Only a pressure can follow the deformation (as in code_aster).
      const auto& l = load->load;
      std::string other;
      if (!l.imposed.empty()) other = l.kinematic ? "MECA_IMPO" : "DDL_IMPO";
      else if (!l.nodalForces.empty()) other = "FORCE_NODALE";
      else if (!l.edgeForces.empty()) other = "FORCE_CONTOUR";
      else if (!l.bodyForces.empty()) other = "FORCE_INTERNE";
      if (!other.empty())
        throw Error(occ.path + ": TYPE_CHARGE='SUIV' applies to PRES_REP only, and the load " +
                    session.nameOf(*load) + " holds " + other + ": give it in a load of its own with FIXE_CSTE");
      if (l.pressures.empty())
        throw Error(occ.path + ": TYPE_CHARGE='SUIV' applies to PRES_REP, and the load " + session.nameOf(*load) +
                    " holds none");
    }
    if (occ.has("FONC_MULT")) {
      applied.multiplier = functionOf(occ.conceptPtr("FONC_MULT"));
      if (applied.multiplier->parameters().size() != 1 || applied.multiplier->parameters()[0] != "INST")
        throw Error(occ.path + ": FONC_MULT must be a function of INST alone, it has parameters " +
                    expr::joinNames(applied.multiplier->parameters()));
    }
    problem.loads.push_back(applied);
    keep.push_back(load);
  }

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
  const auto& conv = k.factor("CONVERGENCE").front();
  // RESI_GLOB_RELA (1e-6 by default, when RESI_GLOB_MAXI is absent) and/or RESI_GLOB_MAXI.
  settings.useRela = conv.has("RESI_GLOB_RELA");
  if (settings.useRela) settings.resiGlobRela = conv.real("RESI_GLOB_RELA");
  settings.useMaxi = conv.has("RESI_GLOB_MAXI");
  if (settings.useMaxi) settings.resiGlobMaxi = conv.real("RESI_GLOB_MAXI");
  settings.iterGlobMaxi = static_cast<int>(conv.integer("ITER_GLOB_MAXI"));
  settings.arret = conv.text("ARRET") == "OUI";
  const auto& solveur = k.factor("SOLVEUR").front();
  settings.method = solveur.text("METHODE");
  settings.renum = solveur.text("RENUM");
  settings.nprec = solveur.text("STOP_SINGULIER") == "NON" ? 0 : static_cast<int>(solveur.integer("NPREC"));
  settings.print = k.integer("INFO") >= 1;

  // ETAT_INIT: the state to start from (and, for EVOL_NOLI, the initial instant).
  const ResultInstant* initial = nullptr;
  const NodalFieldConcept* initialField = nullptr;
  if (k.has("ETAT_INIT")) {
    const auto& init = k.factor("ETAT_INIT").front();
    if (init.has("EVOL_NOLI")) {
      const auto& prev = static_cast<ResultConcept&>(*init.conceptPtr("EVOL_NOLI"));
      if (prev.model->meshPtr() != model->meshPtr())
        throw Error("ETAT_INIT/EVOL_NOLI was computed on another mesh than MODELE's");
      try {
        initial = &instantOf(prev, init);
      } catch (const Error& e) {
        throw Error("ETAT_INIT: " + std::string(e.what()));
      }
    } else {
      initialField = dynamic_cast<const NodalFieldConcept*>(init.conceptPtr("DEPL").get());
      if (!initialField || isFunctionField(*initialField))
        throw Error("ETAT_INIT/DEPL: " + session.nameOf(*init.conceptPtr("DEPL")) + " is not a field of real nodal values");
      if (initialField->mesh != model->meshPtr())
        throw Error("ETAT_INIT/DEPL: the field is defined on another mesh than MODELE's");
    }
  } else if (reuse) {
    throw Error("reuse=: STAT_NON_LINE continues a result from a state; give ETAT_INIT = {EVOL_NOLI = " +
                session.nameOf(*reuse) + "} (its last instant, or INST / NUME_ORDRE)");
  }
  const double initialTime = initial ? initial->time : 0.0;
  const auto times = instantsOf(k.factor("INCREMENT").front(), settings.subdPas, settings.subdNiveau,
                                initial ? &initialTime : nullptr);

  analysis::MechanicalSystem system(problem);
  std::unique_ptr<analysis::AdditionalTerms> terms;
  if (const auto contact = k.concept<ContactConcept>("CONTACT"))
    terms = analysis::makeContactTerms(system, contact->zones, contact->settings);
  analysis::StaticNonlinear newtonSolver(system, terms.get(), settings);

  std::shared_ptr<ResultConcept> result =
      reuse ? std::static_pointer_cast<ResultConcept>(reuse) : std::make_shared<ResultConcept>(model);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newtonSolver.unknownCount());
  if (initial || initialField) {
    const auto& depl = initial ? ResultConcept::nodalField(*initial, "DEPL") : initialField->field;
    const int nc = static_cast<int>(depl.components.size());
    const int cx = componentIndex(depl, "DX", "ETAT_INIT/DEPL"), cy = componentIndex(depl, "DY", "ETAT_INIT/DEPL");
    for (int n = 0; n < mesh.nodeCount(); ++n)
      for (int c = 0; c < 2; ++c)
        if (system.dof(n, c) >= 0) U(system.dof(n, c)) = depl.values[n * nc + (c == 0 ? cx : cy)];
  }
  if (reuse) {
    // A restart from an earlier instant replaces what the result held after it.
    const double eps = 1e-6 * std::max(1.0, std::fabs(times.front()));
    auto& kept = result->instants;
    kept.erase(std::remove_if(kept.begin(), kept.end(), [&](const ResultInstant& i) { return i.time > times.front() + eps; }),
               kept.end());
  } else {
    // NUME_ORDRE 0: the initial state.
    ResultInstant first;
    first.time = times.front();
    mesh::NodalField depl{"DEPL", {"DX", "DY"}, std::vector<double>(2 * mesh.nodeCount(), 0.0)};
    for (int n = 0; n < mesh.nodeCount(); ++n)
      for (int c = 0; c < 2; ++c)
        if (system.dof(n, c) >= 0) depl.values[2 * n + c] = U(system.dof(n, c));
    if (terms) terms->extendDisplacement(U, depl);
    first.nodal.push_back(depl);
    // The internal forces and stresses of the initial state (zero unless ETAT_INIT).
    Eigen::VectorXd fint, fext;
    system.evaluate(U.head(system.dofCount()), times.front(), fint, fext, nullptr, nullptr);
    mesh::NodalField forc{"FORC_NODA", {"DX", "DY"}, std::vector<double>(2 * mesh.nodeCount(), 0.0)};
    for (int n = 0; n < mesh.nodeCount(); ++n)
      for (int c = 0; c < 2; ++c)
        if (system.dof(n, c) >= 0) forc.values[2 * n + c] = fint(system.dof(n, c));
    first.nodal.push_back(std::move(forc));
    GaussField sief{"SIEF_ELGA", {"SIXX", "SIYY", "SIZZ", "SIXY"}, model->cells(), {}, {}};
    system.gaussStresses(U, sief.offsets, sief.values);
    first.gauss.push_back(std::move(sief));
    result->instants.push_back(first);
  }

  // Every instant goes to disk as soon as it is in the result.
  const std::string stem = session.uniqueOutputStem(session.assignedName.empty() ? "STAT_NON_LINE" : session.assignedName);
  ResultArchive archive(mesh, session.outputFile(stem + ".pvd"), &session.files);
  // The count is what the .pvd on disk lists.
  auto stored = [&](const char* when) {
    return "; " + std::to_string(archive.stored()) + " instant(s) were stored " + when + ", in " +
           archive.path().string();
  };
  try {
    for (const auto& inst : result->instants) archive.add(inst);
  } catch (const Error& e) {
    throw Error(e.what() + stored("before the failure"));
  }
  Messages::info("STAT_NON_LINE: each converged instant is written to " + archive.path().string());

  auto store = [&](const analysis::ConvergedInstant& c) {
    ResultInstant inst;
    inst.index = static_cast<int>(result->instants.size());
    inst.time = c.time;
    inst.newtonIterations = c.iterations;
    mesh::NodalField depl{"DEPL", {"DX", "DY"}, std::vector<double>(2 * mesh.nodeCount(), 0.0)};
    mesh::NodalField reac{"REAC_NODA", {"DX", "DY"}, std::vector<double>(2 * mesh.nodeCount(), 0.0)};
    mesh::NodalField forc{"FORC_NODA", {"DX", "DY"}, std::vector<double>(2 * mesh.nodeCount(), 0.0)};
    for (int n = 0; n < mesh.nodeCount(); ++n)
      for (int comp = 0; comp < 2; ++comp) {
        const int d = system.dof(n, comp);
        if (d < 0) continue;
        depl.values[2 * n + comp] = (*c.U)(d);
        reac.values[2 * n + comp] = (*c.reactions)(d);
        forc.values[2 * n + comp] = (*c.internalForces)(d);
      }
    if (terms) terms->extendDisplacement(*c.U, depl);
    inst.nodal.push_back(std::move(depl));
    inst.nodal.push_back(std::move(reac));
    inst.nodal.push_back(std::move(forc));
    if (terms) terms->outputFields(*c.U, inst.nodal);
    GaussField sief{"SIEF_ELGA", {"SIXX", "SIYY", "SIZZ", "SIXY"}, model->cells(), {}, {}};
    system.gaussStresses(*c.U, sief.offsets, sief.values);
    inst.gauss.push_back(std::move(sief));
    archive.add(inst);  // an instant that is not on disk (full disk) is not in the result either
    result->instants.push_back(std::move(inst));
  };
  try {
    newtonSolver.run(U, times, store);
  } catch (const Interrupted& e) {
    throw Interrupted(e.what() + stored("before it"));
  } catch (const Error& e) {
    // The converged instants stay in the result; the study stops here.
    throw Error(e.what() + stored("before the failure"));
  }
  const auto& st = newtonSolver.statistics();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "STAT_NON_LINE: %zu instants, %d Newton iterations, %d factorizations, %d step cuts; "
                "%d unknowns; %.3f s (assembly %.3f s, linear solver %.3f s)",
                times.size() - 1, st.iterations, st.factorizations, st.cuts, newtonSolver.unknownCount(),
                st.totalSeconds, st.assemblySeconds, st.solveSeconds);
  Messages::info(buf);
  if (k.integer("INFO") >= 2) {
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
  return result;
}

RegisterOperator reg("STAT_NON_LINE", statNonLine);

}  // namespace
}  // namespace aster::lang
