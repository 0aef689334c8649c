// STAT_NON_LINE: quasi-static nonlinear analysis (Newton) over a list of instants.
// The operator reads (the problem, the driver's settings, the initial state, the
// instants), builds (the system, the contact terms, the driver with its convergence
// table), runs, storing each converged instant as it comes, and reports.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <Eigen/LU>

#include "commands/archiving.hpp"
#include "commands/contact_concept.hpp"
#include "commands/elga_field.hpp"
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
#include "mechanics/von_mises_plasticity.hpp"
#include "model/behaviour.hpp"
#include "post/strain_fields.hpp"
#include "fem/mesh_cell_type.hpp"
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

  // Behaviour: ELAS in PETIT everywhere unless COMPORTEMENT says otherwise (the last occurrence wins).
  struct CellBehaviour {
    const Keywords* occurrence = nullptr;  // COMPORTEMENT's, null: ELAS, PETIT
    mechanics::Kinematics kinematics = mechanics::Kinematics::SmallStrain;
  };
  std::vector<CellBehaviour> byCell(mesh.cellCount());
  bool onlyElastic = true;
  for (const auto& occ : k.factor("COMPORTEMENT")) {
    const auto kin = mechanics::kinematicsFromName(occ.text("DEFORMATION"));
    // code_aster: -1, 0, 1 never subdivide; -N subdivides into N sub-steps only where the
    // local integration fails (where it succeeds, the result is that of 0); N > 1 always.
    if (occ.integer("ITER_INTE_PAS") > 1)
      throw Error("COMPORTEMENT: ITER_INTE_PAS=" + std::to_string(occ.integer("ITER_INTE_PAS")) +
                  ": the imposed local subdivision of the step is not available (only ITER_INTE_PAS <= 1); "
                  "DEFI_LIST_INST's ECHEC cuts the global step instead");
    onlyElastic &= occ.text("RELATION") == "ELAS";
    std::vector<int> cells = occ.has("GROUP_MA") || occ.has("MAILLE") ? selectCells(mesh, occ) : model->cells();
    for (int c : cells) byCell[c] = {&occ, kin};
  }
  const auto& cells = model->cells();
  for (int c : cells) problem.kinematics.push_back(byCell[c].kinematics);
  // A problem of ELAS alone keeps MechanicalSystem's own elastic laws (problem.relations empty).
  if (!onlyElastic) {
    model::BehaviourFactory factory;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const int c = cells[i];
      const Keywords* occ = byCell[c].occurrence;
      model::BehaviourSite site;
      site.material = problem.materials->at(c);
      site.cellName = mesh.cellName(c);
      if (!site.material)
        throw Error("cell " + site.cellName + " of the model has no material (AFFE_MATERIAU covers it?)");
      site.materialName = problem.materials->materialName(c);
      site.modelisation = model->modelisation(static_cast<int>(i));
      site.deformation = occ ? occ->text("DEFORMATION") : "PETIT";
      site.kinematics = byCell[c].kinematics;
      model::IntegrationSettings integration;
      if (occ) {
        integration.maxIterations = static_cast<int>(occ->integer("ITER_INTE_MAXI"));
        integration.tolerance = occ->real("RESI_INTE_RELA");
        integration.theta = occ->real("PARM_THETA");
        if (occ->has("ALGO_INTE")) integration.algorithm = occ->text("ALGO_INTE");
      }
      problem.relations.push_back(factory.law(occ ? occ->text("RELATION") : "ELAS", site, integration));
    }
  }

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
  settings.mumps = choice.mumps;
  settings.gcpc = choice.gcpc;
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

// ETAT_INIT: the state to start from, an instant of an EVOL_NOLI or fields (DEPL,
// SIGM, VARI), or nothing.
struct InitialState {
  const ResultInstant* instant = nullptr;  // EVOL_NOLI's (it gives the initial instant too)
  const NodalFieldConcept* field = nullptr;  // DEPL's
  const CellField* stresses = nullptr;       // SIGM's or the instant's SIEF_ELGA
  const CellField* variables = nullptr;      // VARI's or the instant's VARI_ELGA
  const CellFieldConcept* stressConcept = nullptr;    // SIGM's (its components may be absent on some cells)
  const CellFieldConcept* variableConcept = nullptr;  // VARI's
  bool given() const { return instant || field || stresses || variables; }
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
      state.stresses = ResultConcept::cellField(*state.instant, "SIEF_ELGA");
      state.variables = ResultConcept::cellField(*state.instant, "VARI_ELGA");
    }
    if (init.has("DEPL")) {
      state.field = dynamic_cast<const NodalFieldConcept*>(init.conceptPtr("DEPL").get());
      if (!state.field || isFunctionField(*state.field))
        throw Error("ETAT_INIT/DEPL: " + session.nameOf(*init.conceptPtr("DEPL")) + " is not a field of real nodal values");
      if (state.field->mesh != model.meshPtr())
        throw Error("ETAT_INIT/DEPL: the field is defined on another mesh than MODELE's");
    }
    for (const char* key : {"SIGM", "VARI"}) {
      if (!init.has(key)) continue;
      const auto* f = dynamic_cast<const CellFieldConcept*>(init.conceptPtr(key).get());
      const std::string name = session.nameOf(*init.conceptPtr(key));
      if (!f || f->field.location != CellLocation::GaussPoints)
        throw Error(std::string("ETAT_INIT/") + key + ": " + name + " is not a field at Gauss points (ELGA)");
      if (f->mesh != model.meshPtr())
        throw Error(std::string("ETAT_INIT/") + key + ": " + name + " is defined on another mesh than MODELE's");
      (std::string(key) == "SIGM" ? state.stressConcept : state.variableConcept) = f;
      (std::string(key) == "SIGM" ? state.stresses : state.variables) = &f->field;
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

// A field at Gauss points laid out as MechanicalSystem keeps its state: `names` per
// Gauss point of each cell of the model, zero where the field lacks the cell or the component.
std::vector<double> modelLayout(const CellField& f, const CellFieldConcept* concept,
                                const analysis::MechanicalSystem& system, const std::vector<std::string>& names,
                                const std::string& what) {
  const auto& mesh = system.model().mesh();
  const auto& cells = system.model().cells();
  std::vector<int> indexOf(mesh.cellCount(), -1);
  for (std::size_t i = 0; i < f.cells.size(); ++i) indexOf[f.cells[i]] = static_cast<int>(i);
  std::vector<int> column(names.size(), -1);
  for (std::size_t j = 0; j < names.size(); ++j)
    for (std::size_t c = 0; c < f.components.size(); ++c)
      if (f.components[c] == names[j]) column[j] = static_cast<int>(c);
  std::vector<double> out;
  const std::size_t nc = f.components.size();
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const int points = system.gaussPoints(static_cast<int>(k));
    const int i = indexOf[cells[k]];
    if (i >= 0 && pointsOf(f, i) != points)
      throw Error(what + ": the field has " + std::to_string(pointsOf(f, i)) + " points on cell " +
                  mesh.cellName(cells[k]) + ", whose element has " + std::to_string(points) + " Gauss points");
    for (int q = 0; q < points; ++q)
      for (std::size_t j = 0; j < names.size(); ++j) {
        const bool present = i >= 0 && column[j] >= 0 && (!concept || componentPresent(*concept, i, column[j]));
        out.push_back(present ? f.values[f.offsets[i] + q * nc + column[j]] : 0.0);
      }
  }
  return out;
}

// The cells (indices in the model) whose law integrates from the second Piola-Kirchhoff
// stress S while SIEF_ELGA holds Cauchy's: a von Mises law in GROT_GDEP, any law in
// GDEF_LOG (its element keeps S too).
bool keepsPiolaKirchhoff(const analysis::MechanicalSystem& system, std::size_t k) {
  const auto& problem = system.problem();
  if (!system.hasHistory(static_cast<int>(k))) return false;
  if (problem.kinematics[k] == mechanics::Kinematics::Logarithmic) return true;
  return k < problem.relations.size() && problem.kinematics[k] == mechanics::Kinematics::GreenLagrange &&
         dynamic_cast<const mechanics::VonMisesPlasticity*>(problem.relations[k].get());
}

// The Cauchy stresses of ETAT_INIT made the laws' measure where a law keeps S:
// S = J F^-1 sigma F^-T, F = I + grad u of the initial DEPL at each Gauss point (F33 =
// 1 in D_PLAN, 1 + u_r / r in AXIS). In C_PLAN F33 comes from the law's own
// plane stress condition and is not known from the displacements: refused there.
void cauchyToPiolaKirchhoff(const analysis::MechanicalSystem& system, const Eigen::VectorXd& U,
                            std::vector<double>& stresses) {
  const auto& model = system.model();
  const auto& mesh = model.mesh();
  std::size_t at = 0;
  std::vector<double> X, u, F;
  for (std::size_t k = 0; k < model.cells().size(); ++k) {
    const int c = model.cells()[k], points = system.gaussPoints(static_cast<int>(k));
    if (keepsPiolaKirchhoff(system, k)) {
      if (model.modelisation(static_cast<int>(k)) == mechanics::PlaneHypothesis::PlaneStress)
        throw Error("ETAT_INIT: the stresses (SIEF_ELGA, Cauchy's) of cell " + mesh.cellName(c) +
                    " would be converted to the second Piola-Kirchhoff stress its law in "
                    "DEFORMATION='GROT_GDEP' or 'GDEF_LOG' integrates from, and in C_PLAN the out-of-plane stretch this "
                    "needs is not known from the displacements: restarting such a law in C_PLAN from "
                    "stresses is not available (D_PLAN and AXIS are)");
      X.clear();
      u.clear();
      for (int n : mesh.cellNodes(c)) {
        const auto p = mesh.node(n);
        X.push_back(p(0));
        X.push_back(p(1));
        for (int d = 0; d < 2; ++d) u.push_back(system.dof(n, d) >= 0 ? U(system.dof(n, d)) : 0.0);
      }
      F.resize(static_cast<std::size_t>(points) * post::kGradientComponents);
      post::gaussDeformationGradients(fem::referenceCell(mesh.cellType(c), "ETAT_INIT"), X.data(), u.data(),
                                      model.axisymmetric(), F.data());
      for (int q = 0; q < points; ++q) {
        const double* f = F.data() + q * post::kGradientComponents;
        double* s = stresses.data() + at + 4 * q;
        Eigen::Matrix2d F2;
        F2 << f[0], f[1], f[2], f[3];
        const double J = F2.determinant() * f[4];
        if (!(J > 0))
          throw Error("ETAT_INIT: the initial displacement inverts cell " + mesh.cellName(c) + " (det F = " +
                      format::shortest(J) + " at its Gauss point " + std::to_string(q + 1) + ")");
        Eigen::Matrix2d sigma;
        sigma << s[0], s[3], s[3], s[1];
        const Eigen::Matrix2d Finv = F2.inverse();
        const Eigen::Matrix2d S = J * Finv * sigma * Finv.transpose();
        s[0] = S(0, 0);
        s[1] = S(1, 1);
        s[2] = J * s[2] / (f[4] * f[4]);
        s[3] = S(0, 1);
      }
    }
    at += 4 * static_cast<std::size_t>(points);
  }
}

// The laws' state of ETAT_INIT: U and, for the laws with history, the stresses and
// internal variables of SIGM / VARI or of EVOL_NOLI's instant (Cauchy stresses made
// second Piola-Kirchhoff ones where a law keeps those).
void setInitialLawState(const InitialState& state, analysis::MechanicalSystem& system, const Eigen::VectorXd& U) {
  if (!state.given()) return;
  std::vector<double> stresses, variables;
  if (state.stresses) {
    stresses = modelLayout(*state.stresses, state.stressConcept, system, {"SIXX", "SIYY", "SIZZ", "SIXY"},
                           "ETAT_INIT/SIGM");
    cauchyToPiolaKirchhoff(system, U, stresses);
  }
  if (state.variables) {
    std::vector<std::string> names;
    for (int v = 1; v <= system.internalVariableCount(); ++v) names.push_back("V" + std::to_string(v));
    for (const auto& c : state.variables->components)
      if (std::find(names.begin(), names.end(), c) == names.end())
        throw Error("ETAT_INIT/VARI: the field has the component " + c + ", and the laws of the model have " +
                    std::to_string(system.internalVariableCount()) + " internal variables (V1 ... V" +
                    std::to_string(system.internalVariableCount()) + ")");
    variables = modelLayout(*state.variables, state.variableConcept, system, names, "ETAT_INIT/VARI");
  }
  system.setAcceptedState(U, state.stresses ? &stresses : nullptr, state.variables ? &variables : nullptr);
}

// The run's figures; INFO >= 2 adds the linear solver's.
void reportStatistics(const analysis::StaticNonlinear& newtonSolver, const analysis::NewtonSettings& settings,
                      std::size_t instants, long long info) {
  const auto& st = newtonSolver.statistics();
  // GCPC factorizes its preconditioner only now and then: its own count, not the matrices it was given.
  const int factorizations =
      settings.method == "GCPC" ? newtonSolver.solverStatistics().factorizeCount : st.factorizations;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "STAT_NON_LINE: %zu instants, %d Newton iterations, %d factorizations, %d step cuts; "
                "%d unknowns; %.3f s (assembly %.3f s, linear solver %.3f s)",
                instants, st.iterations, factorizations, st.cuts, newtonSolver.unknownCount(),
                st.totalSeconds, st.assemblySeconds, st.solveSeconds);
  std::string line = buf;
  if (settings.lineSearch)
    line += "; line search: " + std::to_string(st.lineSearchTrials) + " residuals evaluated";
  if (st.statusLoops > 0)
    line += "; active-set loop: " + std::to_string(st.statusLoops) + " re-solves with new statuses (" +
            std::to_string(st.statusSolves) + " solves)";
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
    line = buf;
    if (settings.method == "GCPC")  // factorizeCount: the preconditioner's
      line += "; " + std::to_string(ls.krylovIterations) + " conjugate gradient iterations over " +
              std::to_string(ls.solveCount) + " solves";
    Messages::info(line);
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
  result->variableNames = system.internalVariableNames();
  for (auto kin : problem.kinematics) result->largeStrain |= kin != mechanics::Kinematics::SmallStrain;
  Eigen::VectorXd U = Eigen::VectorXd::Zero(newtonSolver.unknownCount());
  setInitialUnknowns(initial, system, U);
  setInitialLawState(initial, system, U);
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
  archive.setVariableNames(result->variableNames);
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
