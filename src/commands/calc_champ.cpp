// CALC_CHAMP: fields derived from a result (evol_elas, evol_noli) at its
// instants, added to it (reuse) or to a copy of it:
// - CONTRAINTE: SIEF_ELGA (the stored one; computed from DEPL with the
//   materials' elasticity when an evol_elas was stored without it), SIGM_ELGA (the
//   same values: on continuum elements code_aster's SIGM is SIEF, the Cauchy stress),
//   SIEF_ELNO / SIGM_ELNO (extrapolated, post::modelGaussToNodes), SIEF_NOEU /
//   SIGM_NOEU (the mean of the ELNO values of the cells around each node);
// - DEFORMATION: EPSI_* (linearized) and EPSG_* (Green-Lagrange) from DEPL;
// - CRITERES: SIEQ_ELGA from SIEF_ELGA, SIEQ_ELNO from SIGM_ELNO, SIEQ_NOEU;
// - FORCE: FORC_NODA and REAC_NODA, as the operators stored them (STAT_NON_LINE: at every
//   instant, the initial state included);
// - VARI_INTERNE: VARI_ELNO, VARI_NOEU from VARI_ELGA.
// A NOEU field asked for brings its ELNO field into the result too. GROUP_MA
// restricts the cells the fields are computed on (and averaged over).
#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <string>

#include "analysis/mechanical_system.hpp"
#include "commands/field_concepts.hpp"
#include "commands/function_concepts.hpp"
#include "commands/instant_selection.hpp"
#include "commands/model_concepts.hpp"
#include "commands/result_concepts.hpp"
#include "commands/selection.hpp"
#include "core/error.hpp"
#include "core/messages.hpp"
#include "core/number_format.hpp"
#include "fem/mesh_cell_type.hpp"
#include "lang/operators.hpp"
#include "post/gauss_to_nodes.hpp"
#include "post/strain_fields.hpp"
#include "post/stress_invariants.hpp"

namespace aster::lang {
namespace {

const std::vector<std::string> kStressComponents{"SIXX", "SIYY", "SIZZ", "SIXY"};
const std::vector<std::string> kStrainComponents{"EPXX", "EPYY", "EPZZ", "EPXY"};

// The instants of TOUT_ORDRE (default), NUME_ORDRE, INST or LIST_INST, to complete.
std::vector<ResultInstant*> selectInstants(ResultConcept& r, const Keywords& k) {
  std::vector<ResultInstant*> out;
  for (const ResultInstant* i : selectedInstants(r, k))
    out.push_back(&r.instants[static_cast<std::size_t>(i - r.instants.data())]);
  return out;
}

// A field on cells restricted to the cells flagged in `keep` (per mesh cell), renamed.
CellField restricted(const CellField& f, const std::vector<char>& keep, const std::string& name) {
  CellField out{name, f.components, {}, {0}, {}, f.location};
  for (std::size_t k = 0; k < f.cells.size(); ++k) {
    if (!keep[f.cells[k]]) continue;
    out.cells.push_back(f.cells[k]);
    out.values.insert(out.values.end(), f.values.begin() + f.offsets[k], f.values.begin() + f.offsets[k + 1]);
    out.offsets.push_back(static_cast<int>(out.values.size()));
  }
  return out;
}

// ELGA -> ELNO on every cell of the field.
CellField toNodes(const CellField& elga, const model::Model& model, const std::string& name) {
  const auto& mesh = model.mesh();
  CellField out{name, elga.components, elga.cells, {0}, {}, CellLocation::Nodes};
  const int nc = static_cast<int>(elga.components.size());
  for (std::size_t k = 0; k < elga.cells.size(); ++k) {
    const int cell = elga.cells[k];
    const fem::CellType t = fem::referenceCell(mesh.cellType(cell), name.c_str());
    const Eigen::MatrixXd& G = post::modelGaussToNodes(t, model.axisymmetric());
    if (pointsOf(elga, k) != G.cols())
      throw Error(name + ": cell " + mesh.cellName(cell) + " holds " + std::to_string(pointsOf(elga, k)) + " points in " +
                  elga.name + ", not the " + std::to_string(G.cols()) + " of the model's integration rule");
    const std::size_t at = out.values.size();
    out.values.resize(at + G.rows() * nc);
    post::extrapolateToNodes(G, elga.values.data() + elga.offsets[k], nc, out.values.data() + at);
    out.offsets.push_back(static_cast<int>(out.values.size()));
  }
  return out;
}

// ELNO -> NOEU: at each node, the mean of the values of the cells holding it;
// `support` receives the nodes that have a value.
mesh::NodalField toNodal(const CellField& elno, const mesh::Mesh& mesh, const std::string& name,
                         std::vector<int>& support) {
  const std::size_t nc = elno.components.size();
  mesh::NodalField out{name, elno.components, std::vector<double>(mesh.nodeCount() * nc, 0.0)};
  std::vector<int> count(mesh.nodeCount(), 0);
  for (std::size_t k = 0; k < elno.cells.size(); ++k) {
    const auto nodes = mesh.cellNodes(elno.cells[k]);
    for (int a = 0; a < nodes.size(); ++a) {
      ++count[nodes[a]];
      for (std::size_t c = 0; c < nc; ++c) out.values[nodes[a] * nc + c] += elno.values[elno.offsets[k] + a * nc + c];
    }
  }
  support.clear();
  for (int n = 0; n < mesh.nodeCount(); ++n) {
    if (!count[n]) continue;
    support.push_back(n);
    for (std::size_t c = 0; c < nc; ++c) out.values[n * nc + c] /= count[n];
  }
  return out;
}

// SIEQ at every point of a stress field (ELGA or ELNO alike).
CellField equivalents(const CellField& stress, const std::string& name) {
  CellField out{name, post::equivalentStressComponents(), stress.cells, {0}, {}, stress.location};
  const std::size_t nc = stress.components.size();
  for (std::size_t k = 0; k < stress.cells.size(); ++k) {
    for (int q = 0; q < pointsOf(stress, k); ++q) {
      const std::size_t at = out.values.size();
      out.values.resize(at + post::kEquivalentStressComponents);
      post::equivalentStresses(stress.values.data() + stress.offsets[k] + q * nc, out.values.data() + at);
    }
    out.offsets.push_back(static_cast<int>(out.values.size()));
  }
  return out;
}

void store(ResultInstant& inst, CellField f) {
  for (auto& g : inst.cells)
    if (g.name == f.name) {
      g = std::move(f);
      return;
    }
  inst.cells.push_back(std::move(f));
}

void storeNodal(ResultInstant& inst, mesh::NodalField f, std::vector<int> support, const model::Model& model) {
  int modelNodes = 0;
  for (int n = 0; n < model.mesh().nodeCount(); ++n) modelNodes += model.nodeInModel(n) ? 1 : 0;
  if (static_cast<int>(support.size()) == modelNodes) inst.nodalSupport.erase(f.name);
  else inst.nodalSupport[f.name] = std::move(support);
  for (auto& g : inst.nodal)
    if (g.name == f.name) {
      g = std::move(f);
      return;
    }
  inst.nodal.push_back(std::move(f));
}

// What the computation of one instant reads: the model, its materials, the cells.
struct Context {
  std::shared_ptr<model::Model> model;
  std::shared_ptr<const model::MaterialField> materials;
  std::vector<int> cells;        // mesh cells of the model the fields are computed on
  std::vector<char> keep;        // per mesh cell: in `cells`
  std::vector<int> modelIndex;   // per mesh cell: its index in model->cells(), -1 when none
  bool linearResult = false;     // evol_elas
  bool largeStrain = false;      // computed with DEFORMATION='GROT_GDEP'
  // Built on first use: the elastic system that computes SIEF_ELGA when the result lacks it.
  std::unique_ptr<analysis::MechanicalSystem> elasticSystem;
};

const model::ElasticMaterial& materialOf(const Context& ctx, int cell, const std::string& why) {
  const model::ElasticMaterial* m = ctx.materials ? ctx.materials->at(cell) : nullptr;
  if (!m)
    throw Error(why + " needs the material of cell " + ctx.model->mesh().cellName(cell) +
                (ctx.materials ? ", which has none (AFFE_MATERIAU)" : ": give CHAM_MATER"));
  if (!m->hasElas)
    throw Error(why + " needs ELAS in DEFI_MATERIAU of material " + ctx.materials->materialName(cell) + " (cell " +
                ctx.model->mesh().cellName(cell) + ")");
  return *m;
}

// EPSI_ELGA or EPSG_ELGA from DEPL.
CellField strains(const Context& ctx, const mesh::NodalField& depl, post::StrainMeasure measure,
                  const std::string& name) {
  const auto& mesh = ctx.model->mesh();
  const int cx = componentIndex(depl.components, "DX", "DEPL"), cy = componentIndex(depl.components, "DY", "DEPL");
  const std::size_t dnc = depl.components.size();
  CellField out{name, kStrainComponents, ctx.cells, {0}, {}, CellLocation::GaussPoints};
  std::vector<double> X, u;
  for (int cell : ctx.cells) {
    const fem::CellType t = fem::referenceCell(mesh.cellType(cell), name.c_str());
    post::OutOfPlaneStrain zz;
    switch (ctx.model->modelisation(ctx.modelIndex[cell])) {
      case model::Modelisation::PlaneStrain: break;
      case model::Modelisation::PlaneStress:
        zz.planeStress = true;
        zz.nu = materialOf(ctx, cell, name + " in C_PLAN (EPZZ from s_zz = 0)").NU;
        break;
      case model::Modelisation::Axisymmetric: zz.axisymmetric = true; break;
    }
    const auto nodes = mesh.cellNodes(cell);
    X.clear();
    u.clear();
    for (int n : nodes) {
      const auto p = mesh.node(n);
      X.push_back(p(0));
      X.push_back(p(1));
      u.push_back(depl.values[n * dnc + cx]);
      u.push_back(depl.values[n * dnc + cy]);
    }
    const std::size_t at = out.values.size();
    out.values.resize(at + post::strainPointCount(t, zz.axisymmetric) * post::kStrainComponents);
    post::gaussStrains(t, X.data(), u.data(), measure, zz, out.values.data() + at);
    out.offsets.push_back(static_cast<int>(out.values.size()));
  }
  return out;
}

// EPSP_ELGA: EPSI_ELGA less the elastic strain of SIEF_ELGA (ELAS's E and NU), per
// Gauss point of ctx.cells; in C_PLAN EPZZ = -(EPXX + EPYY), the plastic strain being
// deviatoric (the total EPZZ is not known from DEPL).
CellField plasticStrains(const Context& ctx, const ResultInstant& inst, const std::string& at) {
  const CellField* stored = ResultConcept::cellField(inst, "SIEF_ELGA");
  if (!stored) throw Error("EPSP_ELGA needs the stresses SIEF_ELGA, which the result does not hold at " + at);
  const CellField sief = restricted(*stored, ctx.keep, "SIEF_ELGA");
  CellField out = strains(ctx, ResultConcept::nodalField(inst, "DEPL"), post::StrainMeasure::Linearized, "EPSP_ELGA");
  const auto& mesh = ctx.model->mesh();
  const int sxx = componentIndex(sief.components, "SIXX", "SIEF_ELGA"),
            syy = componentIndex(sief.components, "SIYY", "SIEF_ELGA"),
            szz = componentIndex(sief.components, "SIZZ", "SIEF_ELGA"),
            sxy = componentIndex(sief.components, "SIXY", "SIEF_ELGA");
  const std::size_t snc = sief.components.size();
  for (std::size_t k = 0; k < out.cells.size(); ++k) {
    const int cell = out.cells[k];
    if (pointsOf(sief, k) != pointsOf(out, k))
      throw Error("EPSP_ELGA: SIEF_ELGA has " + std::to_string(pointsOf(sief, k)) + " points on cell " +
                  mesh.cellName(cell) + ", the strains " + std::to_string(pointsOf(out, k)));
    const auto& m = materialOf(ctx, cell, "EPSP_ELGA");
    const bool planeStress = ctx.model->modelisation(ctx.modelIndex[cell]) == model::Modelisation::PlaneStress;
    for (int q = 0; q < pointsOf(out, k); ++q) {
      const double* s = sief.values.data() + sief.offsets[k] + q * snc;
      double* e = out.values.data() + out.offsets[k] + q * post::kStrainComponents;
      const double trace = s[sxx] + s[syy] + s[szz];
      e[0] -= ((1 + m.NU) * s[sxx] - m.NU * trace) / m.E;
      e[1] -= ((1 + m.NU) * s[syy] - m.NU * trace) / m.E;
      e[2] = planeStress ? -(e[0] + e[1]) : e[2] - ((1 + m.NU) * s[szz] - m.NU * trace) / m.E;
      e[3] -= (1 + m.NU) * s[sxy] / m.E;
    }
  }
  return out;
}

// SIEF_ELGA of an evol_elas stored without it: linear elasticity at DEPL.
CellField elasticStresses(Context& ctx, const mesh::NodalField& depl) {
  if (!ctx.elasticSystem) {
    for (int cell : ctx.model->cells()) materialOf(ctx, cell, "SIEF_ELGA (not stored in the result)");
    analysis::MechanicalProblem problem;
    problem.model = ctx.model;
    problem.materials = ctx.materials;
    problem.kinematics.assign(ctx.model->cells().size(), mechanics::Kinematics::SmallStrain);
    ctx.elasticSystem = std::make_unique<analysis::MechanicalSystem>(problem);
  }
  const analysis::MechanicalSystem& system = *ctx.elasticSystem;
  Eigen::VectorXd U = Eigen::VectorXd::Zero(system.dofCount());
  const int cx = componentIndex(depl.components, "DX", "DEPL"), cy = componentIndex(depl.components, "DY", "DEPL");
  const std::size_t nc = depl.components.size();
  for (int n = 0; n < ctx.model->mesh().nodeCount(); ++n)
    for (int c = 0; c < 2; ++c)
      if (system.dof(n, c) >= 0) U(system.dof(n, c)) = depl.values[n * nc + (c == 0 ? cx : cy)];
  CellField sief{"SIEF_ELGA", kStressComponents, ctx.model->cells(), {}, {}, CellLocation::GaussPoints};
  system.gaussStresses(U, sief.offsets, sief.values);
  return sief;
}

bool asked(const std::set<std::string>& options, std::initializer_list<const char*> names) {
  for (const char* n : names)
    if (options.count(n)) return true;
  return false;
}

// Computes the options at one instant: `done` receives the names of the fields
// stored, `notes` what was asked for and left absent.
void computeInstant(Context& ctx, const std::set<std::string>& options, ResultInstant& inst,
                    std::set<std::string>& done, std::vector<std::string>& notes) {
  const auto& mesh = ctx.model->mesh();
  const std::string at = "NUME_ORDRE " + std::to_string(inst.index) + " (INST " + format::asterValue(inst.time) + ")";

  // Stresses.
  if (asked(options, {"SIEF_ELGA", "SIGM_ELGA", "SIEF_ELNO", "SIGM_ELNO", "SIEF_NOEU", "SIGM_NOEU", "SIEQ_ELGA",
                      "SIEQ_ELNO", "SIEQ_NOEU"})) {
    CellField sief;
    if (const CellField* stored = ResultConcept::cellField(inst, "SIEF_ELGA")) {
      sief = restricted(*stored, ctx.keep, "SIEF_ELGA");
    } else {
      ResultConcept::requireNotExcluded(inst, "SIEF_ELGA");
      if (!ctx.linearResult)
        throw Error("SIEF_ELGA is not stored in the result at " + at + ": the stresses of an evol_noli are its own");
      CellField all = elasticStresses(ctx, ResultConcept::nodalField(inst, "DEPL"));
      sief = restricted(all, ctx.keep, "SIEF_ELGA");
      if (options.count("SIEF_ELGA")) store(inst, sief);
    }
    if (options.count("SIEF_ELGA")) done.insert("SIEF_ELGA");  // kept as stored, or computed
    if (options.count("SIGM_ELGA")) {
      CellField sigm = sief;
      sigm.name = "SIGM_ELGA";
      store(inst, std::move(sigm));
      done.insert("SIGM_ELGA");
    }
    if (options.count("SIEQ_ELGA")) {
      store(inst, equivalents(sief, "SIEQ_ELGA"));
      done.insert("SIEQ_ELGA");
    }
    if (asked(options, {"SIEF_ELNO", "SIGM_ELNO", "SIEF_NOEU", "SIGM_NOEU", "SIEQ_ELNO", "SIEQ_NOEU"})) {
      const CellField elno = toNodes(sief, *ctx.model, "SIGM_ELNO");
      for (const char* prefix : {"SIEF", "SIGM"}) {
        const std::string e = std::string(prefix) + "_ELNO", n = std::string(prefix) + "_NOEU";
        if (options.count(e) || options.count(n)) {
          CellField f = elno;
          f.name = e;
          store(inst, f);
          done.insert(e);
        }
        if (options.count(n)) {
          std::vector<int> support;
          mesh::NodalField nodal = toNodal(elno, mesh, n, support);
          storeNodal(inst, std::move(nodal), std::move(support), *ctx.model);
          done.insert(n);
        }
      }
      if (asked(options, {"SIEQ_ELNO", "SIEQ_NOEU"})) {
        CellField eq = equivalents(elno, "SIEQ_ELNO");
        if (options.count("SIEQ_NOEU")) {
          std::vector<int> support;
          mesh::NodalField nodal = toNodal(eq, mesh, "SIEQ_NOEU", support);
          storeNodal(inst, std::move(nodal), std::move(support), *ctx.model);
          done.insert("SIEQ_NOEU");
        }
        store(inst, std::move(eq));
        done.insert("SIEQ_ELNO");
      }
    }
  }

  // A strain field at the Gauss points, and what was asked of it at cell nodes and nodes.
  auto storeStrains = [&](CellField elga, const std::string& prefix) {
    const std::string g = prefix + "_ELGA", e = prefix + "_ELNO", n = prefix + "_NOEU";
    if (options.count(e) || options.count(n)) {
      CellField elno = toNodes(elga, *ctx.model, e);
      if (options.count(n)) {
        std::vector<int> support;
        mesh::NodalField nodal = toNodal(elno, mesh, n, support);
        storeNodal(inst, std::move(nodal), std::move(support), *ctx.model);
        done.insert(n);
      }
      store(inst, std::move(elno));
      done.insert(e);
    }
    if (options.count(g)) {
      store(inst, std::move(elga));
      done.insert(g);
    }
  };

  // Strains.
  for (const char* prefix : {"EPSI", "EPSG"}) {
    const std::string g = std::string(prefix) + "_ELGA", e = std::string(prefix) + "_ELNO",
                      n = std::string(prefix) + "_NOEU";
    if (!asked(options, {g.c_str(), e.c_str(), n.c_str()})) continue;
    const auto measure = std::string(prefix) == "EPSI" ? post::StrainMeasure::Linearized
                                                       : post::StrainMeasure::GreenLagrange;
    storeStrains(strains(ctx, ResultConcept::nodalField(inst, "DEPL"), measure, g), prefix);
  }

  // Plastic strains.
  if (asked(options, {"EPSP_ELGA", "EPSP_ELNO", "EPSP_NOEU"})) {
    if (ctx.largeStrain)
      throw Error("EPSP_ELGA is the small-strain plastic strain (EPSI less the elastic strain of SIEF_ELGA), and "
                  "the result was computed with DEFORMATION='GROT_GDEP': it is not available there");
    storeStrains(plasticStrains(ctx, inst, at), "EPSP");
  }

  // Internal variables.
  if (asked(options, {"VARI_ELNO", "VARI_NOEU"})) {
    const CellField* vari = ResultConcept::cellField(inst, "VARI_ELGA");
    if (!vari)
      throw Error("VARI_INTERNE: the result has no internal variables (VARI_ELGA) at " + at +
                  ": its behaviour (ELAS) has none");
    CellField elno = toNodes(restricted(*vari, ctx.keep, "VARI_ELGA"), *ctx.model, "VARI_ELNO");
    if (options.count("VARI_NOEU")) {
      std::vector<int> support;
      mesh::NodalField nodal = toNodal(elno, mesh, "VARI_NOEU", support);
      storeNodal(inst, std::move(nodal), std::move(support), *ctx.model);
      done.insert("VARI_NOEU");
    }
    store(inst, std::move(elno));
    done.insert("VARI_ELNO");
  }

  // Nodal forces: stored by the operators with each instant.
  for (const char* name : {"FORC_NODA", "REAC_NODA"}) {
    if (!options.count(name)) continue;
    bool stored = false;
    for (const auto& f : inst.nodal) stored = stored || f.name == name;
    if (stored) done.insert(name);
    else notes.push_back(std::string(name) + " is not stored at " + at +
                         " (the operator that made the result did not store it) and stays absent");
  }
}

ConceptPtr calcChamp(const Keywords& k, Session& session, ConceptPtr reuse) {
  const auto source = std::static_pointer_cast<ResultConcept>(k.conceptPtr("RESULTAT"));
  if (reuse && reuse != source)
    throw Error("reuse=" + session.nameOf(*reuse) + ": CALC_CHAMP completes the result it reads; give RESULTAT = " +
                session.nameOf(*reuse));
  Context ctx;
  ctx.model = source->model;
  if (k.has("MODELE")) {
    auto m = k.concept<ModelConcept>("MODELE")->model;
    if (m->meshPtr() != source->model->meshPtr())
      throw Error("MODELE is built on another mesh than the result's");
    ctx.model = m;
  }
  ctx.materials = source->materials;
  if (k.has("CHAM_MATER")) {
    auto mat = k.concept<MaterialFieldConcept>("CHAM_MATER");
    if (mat->mesh != ctx.model->meshPtr()) throw Error("CHAM_MATER is built on another mesh than the result's");
    ctx.materials = mat->field;
  }
  ctx.linearResult = source->typeName() == "evol_elas";
  ctx.largeStrain = source->largeStrain;
  const auto& mesh = ctx.model->mesh();
  ctx.modelIndex.assign(mesh.cellCount(), -1);
  for (std::size_t i = 0; i < ctx.model->cells().size(); ++i) ctx.modelIndex[ctx.model->cells()[i]] = static_cast<int>(i);
  ctx.keep.assign(mesh.cellCount(), 0);
  if (k.has("GROUP_MA") || k.has("MAILLE")) {
    for (int c : selectCells(mesh, k))
      if (ctx.modelIndex[c] >= 0) ctx.keep[c] = 1;
  } else {
    for (int c : ctx.model->cells()) ctx.keep[c] = 1;
  }
  for (int c : ctx.model->cells())
    if (ctx.keep[c]) ctx.cells.push_back(c);
  if (ctx.cells.empty()) throw Error("GROUP_MA: no cell of these groups carries a 2D element of the model");

  std::set<std::string> options;
  for (const char* group : {"CONTRAINTE", "DEFORMATION", "CRITERES", "FORCE", "VARI_INTERNE"})
    if (k.has(group))
      for (const auto& name : k.texts(group)) options.insert(name);

  std::shared_ptr<ResultConcept> result = source;
  if (!reuse) {
    result = std::make_shared<ResultConcept>(source->model, source->typeName());
    result->materials = source->materials;
    result->variableNames = source->variableNames;
    result->largeStrain = source->largeStrain;
  }
  std::vector<ResultInstant*> instants = selectInstants(*source, k);
  if (!reuse) {
    // The new result holds the instants computed, with their fields and the new ones.
    for (const ResultInstant* i : instants) result->instants.push_back(*i);
    instants.clear();
    for (auto& i : result->instants) instants.push_back(&i);
  }
  std::set<std::string> done;
  std::vector<std::string> notes;
  for (ResultInstant* inst : instants) computeInstant(ctx, options, *inst, done, notes);

  std::string list;
  for (const auto& n : done) list += (list.empty() ? "" : ", ") + n;
  Messages::info("CALC_CHAMP: " + (list.empty() ? std::string("no field") : list) + " at " +
                 std::to_string(instants.size()) + " instant(s), on " + std::to_string(ctx.cells.size()) + " cell(s)");
  for (const auto& n : notes) Messages::info("CALC_CHAMP: " + n);
  return result;
}

RegisterOperator reg("CALC_CHAMP", calcChamp);

}  // namespace
}  // namespace aster::lang
