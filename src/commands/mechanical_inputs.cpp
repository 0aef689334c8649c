#include "commands/mechanical_inputs.hpp"

#include "commands/function_concepts.hpp"
#include "core/error.hpp"

namespace aster::lang {

void readExcit(const Keywords& k, Session& session, const std::shared_ptr<model::Model>& model,
               analysis::MechanicalProblem& problem, std::vector<std::shared_ptr<LoadConcept>>& keep) {
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
      if (!expr::takesOnly(*applied.multiplier, "INST"))
        throw Error(occ.path + ": FONC_MULT must be a function of INST alone, it has parameters " +
                    expr::joinNames(applied.multiplier->parameters()));
    }
    problem.loads.push_back(applied);
    keep.push_back(load);
  }
}

namespace {

// A nodal field of components DX, DY from a vector over the unknowns (0 where a node has none).
mesh::NodalField nodalField(const std::string& name, const analysis::MechanicalSystem& system,
                            const Eigen::VectorXd& values) {
  const int nodes = system.model().mesh().nodeCount();
  mesh::NodalField f{name, {"DX", "DY"}, std::vector<double>(2 * nodes, 0.0)};
  for (int n = 0; n < nodes; ++n)
    for (int c = 0; c < 2; ++c)
      if (system.dof(n, c) >= 0) f.values[2 * n + c] = values(system.dof(n, c));
  return f;
}

}  // namespace

ResultInstant resultInstant(const analysis::MechanicalSystem& system, const analysis::AdditionalTerms* terms,
                            double time, const Eigen::VectorXd& U, const Eigen::VectorXd& internalForces,
                            const Eigen::VectorXd* reactions, bool withStresses, bool converged) {
  ResultInstant inst;
  inst.time = time;
  mesh::NodalField depl = nodalField("DEPL", system, U);
  if (terms) terms->extendDisplacement(U, depl);
  inst.nodal.push_back(std::move(depl));
  if (reactions) inst.nodal.push_back(nodalField("REAC_NODA", system, *reactions));
  inst.nodal.push_back(nodalField("FORC_NODA", system, internalForces));
  if (terms && converged) terms->outputFields(U, inst.nodal);
  if (withStresses) {
    CellField sief{"SIEF_ELGA", {"SIXX", "SIYY", "SIZZ", "SIXY"}, system.model().cells(), {}, {}};
    system.gaussStresses(U, sief.offsets, sief.values);
    inst.cells.push_back(std::move(sief));
  }
  if (system.internalVariableCount() > 0) {
    CellField vari{"VARI_ELGA", {}, system.model().cells(), {}, {}};
    for (int v = 1; v <= system.internalVariableCount(); ++v) vari.components.push_back("V" + std::to_string(v));
    system.gaussVariables(vari.offsets, vari.values);
    inst.cells.push_back(std::move(vari));
  }
  return inst;
}

}  // namespace aster::lang
