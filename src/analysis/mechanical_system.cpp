#include "analysis/mechanical_system.hpp"
#include "core/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <map>
#include <tuple>

#include "core/error.hpp"
#include "core/worker_pool.hpp"
#include "expr/expression.hpp"
#include "fem/mesh_cell_type.hpp"
#include "mechanics/isotropic_elasticity.hpp"
#include "mechanics/loads.hpp"
#include "mesh/cell_type.hpp"

namespace aster::analysis {
namespace {


constexpr int kMaxNodes = 9;
constexpr int kMaxGaussPoints = 9;  // QUAD9's full rule
// From this many cells on, the element kernels run on every thread, colour by colour.
constexpr std::size_t kParallelCells = 4096;

// A load value at a point, or an aster::Error naming the load, the point and the
// instant when the function is not a finite number there (NaN, infinity).
double loadValue(const model::SpaceFunction& f, const char* load, const char* component,
                 const std::string& where, double x, double y, double z, double t) {
  if (f.isConstant()) return f(x, y, z, t);
  try {
    return f.checked(x, y, z, t);
  } catch (const Error& e) {
    throw Error(std::string(load) + " " + component + where + " at X = " + format::shortest(x) +
                ", Y = " + format::shortest(y) + ", INST = " + format::shortest(t) + ": " + e.what());
  }
}

}  // namespace

double AppliedLoad::factor(double t) const {
  if (!multiplier) return 1.0;
  const double v = multiplier->evaluate(&t);
  if (std::isfinite(v)) return v;
  std::string why = "the function returns " + format::shortest(v);
  if (const auto* e = dynamic_cast<const expr::Expression*>(multiplier.get())) {
    try {
      e->evaluateChecked(&t);
    } catch (const Error& failure) {
      why = failure.what();
    }
  }
  throw Error("FONC_MULT at INST = " + format::shortest(t) + ": " + why);
}

MechanicalSystem::MechanicalSystem(MechanicalProblem problem) : problem_(std::move(problem)) {
  const model::Model& m = *problem_.model;
  const mesh::Mesh& mesh = m.mesh();
  std::vector<int> perNode(mesh.nodeCount(), 0);
  for (int n = 0; n < mesh.nodeCount(); ++n) perNode[n] = m.nodeInModel(n) ? 2 : 0;
  dofs_ = fem::DofMap(perNode);
  for (const auto& applied : problem_.loads)
    for (const auto& rel : applied.load->relations) {
      for (const auto& term : rel.terms)
        if (!dofs_.count(term.node))
          throw Error(rel.origin + ": node " + mesh.nodeName(term.node) +
                      " carries no element of the model, so no DX, DY");
      relationOrigins_.push_back(rel.origin);
    }
  if (problem_.kinematics.size() != m.cells().size())
    throw Error("internal error: one kinematics per cell of the model is expected");

  if (!problem_.relations.empty() && problem_.relations.size() != m.cells().size())
    throw Error("internal error: one behaviour law per cell of the model is expected");

  // ELAS: one law per (material, modelisation); one kernel per (type, law, kinematics).
  std::map<std::pair<const model::ElasticMaterial*, int>, std::shared_ptr<const mechanics::BehaviourLaw>> elastic;
  std::map<std::tuple<int, const mechanics::BehaviourLaw*, int>, const mechanics::ElementKernel*> cache;
  int statePoints = 0, stateVariables = 0;
  for (std::size_t k = 0; k < m.cells().size(); ++k) {
    const int c = m.cells()[k];
    std::shared_ptr<const mechanics::BehaviourLaw> law;
    if (!problem_.relations.empty()) {
      law = problem_.relations[k];
      if (!law) throw Error("internal error: cell " + mesh.cellName(c) + " of the model has no behaviour law");
      predictsFromAcceptedState_ = predictsFromAcceptedState_ || law->predictsFromAcceptedState();
    } else {
      const model::ElasticMaterial* mat = problem_.materials ? problem_.materials->at(c) : nullptr;
      if (!mat)
        throw Error("cell " + mesh.cellName(c) + " of the model has no material (AFFE_MATERIAU covers it?)");
      if (!mat->hasElas)
        throw Error("RELATION='ELAS' needs ELAS in DEFI_MATERIAU of material " + problem_.materials->materialName(c) +
                    " (cell " + mesh.cellName(c) + ")");
      auto& slot = elastic[{mat, static_cast<int>(m.modelisation(k))}];
      if (!slot) slot = std::make_shared<mechanics::IsotropicElasticity>(mat->E, mat->NU, m.modelisation(k));
      law = slot;
    }
    if (!law->symmetricTangent()) symmetricLaws_ = false;
    const auto key = std::make_tuple(static_cast<int>(mesh.cellType(c)), law.get(),
                                     static_cast<int>(problem_.kinematics[k]));
    auto it = cache.find(key);
    if (it == cache.end()) {
      kernels_.push_back(mechanics::makePlaneKernel(mesh.cellType(c), law, problem_.kinematics[k]));
      it = cache.emplace(key, kernels_.back().get()).first;
    }
    const mechanics::ElementKernel* kernel = it->second;
    if (kernel->gaussPoints() > kMaxGaussPoints) throw Error("internal error: more Gauss points than kMaxGaussPoints");
    std::vector<int> d;
    dofs_.appendNodeDofs(mesh.cellNodes(c).begin(), mesh.cellNodes(c).end(), 2, d);
    Cell cell{c, kernel, elements_.add(d), -1, 0};
    if (kernel->usesHistory()) {
      cell.state = statePoints;
      cell.variables = stateVariables;
      statePoints += kernel->gaussPoints();
      stateVariables += kernel->gaussPoints() * kernel->internalVariables();
      hasHistory_ = true;
    }
    maxVariables_ = std::max(maxVariables_, kernel->internalVariables());
    cells_.push_back(cell);
  }
  if (hasHistory_) {
    acceptedU_ = Eigen::VectorXd::Zero(dofCount());
    acceptedStress_.assign(4 * statePoints, 0.0);
    acceptedVariables_.assign(stateVariables, 0.0);
    naturalVariables_.assign(kMaxGaussPoints * maxVariables_, 0.0);
  }
  if (cells_.size() >= kParallelCells) {
    fem::ElementDofs chunkDofs;
    std::vector<int> d;
    for (std::size_t first = 0; first < cells_.size(); first += kChunkCells) {
      d.clear();
      for (std::size_t c = first; c < std::min(cells_.size(), first + kChunkCells); ++c) {
        const int* cellDofs = elements_.dofs(cells_[c].element);
        d.insert(d.end(), cellDofs, cellDofs + elements_.size(cells_[c].element));
      }
      chunkDofs.add(d);
    }
    try {
      chunkColours_ = fem::colourElements(chunkDofs, dofCount());
    } catch (const Error&) {
      chunkColours_.clear();  // more than 64 colours (a node in very many chunks): serial assembly
    }
  }
  for (const auto& applied : problem_.loads) {
    if (!applied.follower) continue;
    for (const auto& p : applied.load->pressures)
      for (int c : p.cells) {
        std::vector<int> d;
        dofs_.appendNodeDofs(mesh.cellNodes(c).begin(), mesh.cellNodes(c).end(), 2, d);
        pressureEdges_.push_back({c, elements_.add(d), &p.p, &applied});
      }
  }
  // Dead loads that do not depend on time are integrated once.
  for (const auto& applied : problem_.loads) {
    bool timeDependent = false;
    for (const auto& f : applied.load->edgeForces) timeDependent |= f.fx.dependsOnTime() || f.fy.dependsOnTime();
    for (const auto& f : applied.load->bodyForces) timeDependent |= f.fx.dependsOnTime() || f.fy.dependsOnTime();
    for (const auto& f : applied.load->nodalForces) timeDependent |= f.fx.dependsOnTime() || f.fy.dependsOnTime();
    if (!applied.follower)
      for (const auto& p : applied.load->pressures) timeDependent |= p.p.dependsOnTime();
    constantDeadLoads_.push_back(timeDependent ? Eigen::VectorXd() : deadLoadVector(applied, 0.0));
  }
}

void MechanicalSystem::gatherCoords(int meshCell, double* X) const {
  const mesh::Mesh& mesh = problem_.model->mesh();
  const auto nodes = mesh.cellNodes(meshCell);
  const int n = nodes.size();
  for (int a = 0; a < n; ++a) {
    const double* x = mesh.coordinates().data() + 3 * nodes[a];
    X[a] = x[0];
    X[n + a] = x[1];
  }
}

Eigen::VectorXd MechanicalSystem::deadLoadVector(const AppliedLoad& applied, double t) const {
  const model::MechanicalLoad& load = *applied.load;
  const mesh::Mesh& mesh = problem_.model->mesh();
  Eigen::VectorXd F = Eigen::VectorXd::Zero(dofCount());
  // AXIS: loads per radian, weighted by r (FORCE_NODALE is per radian as given).
  const bool axisymmetric = problem_.model->axisymmetric();
  double X[2 * kMaxNodes];
  auto scatter = [&](int cell, const double* fe) {
    const auto nodes = mesh.cellNodes(cell);
    for (int a = 0; a < nodes.size(); ++a) {
      if (!dofs_.count(nodes[a])) continue;
      F(dofs_.dof(nodes[a], 0)) += fe[2 * a];
      F(dofs_.dof(nodes[a], 1)) += fe[2 * a + 1];
    }
  };
  std::string where;
  for (const auto& ef : load.edgeForces) {
    auto traction = [&](const Eigen::Vector2d& p) {
      return Eigen::Vector2d(loadValue(ef.fx, "FORCE_CONTOUR", "FX", where, p(0), p(1), 0.0, t),
                             loadValue(ef.fy, "FORCE_CONTOUR", "FY", where, p(0), p(1), 0.0, t));
    };
    for (int c : ef.cells) {
      where = " on cell " + mesh.cellName(c);
      gatherCoords(c, X);
      fem::dispatchEdge(fem::referenceCell(mesh.cellType(c), "loads"), [&](auto tag) {
        constexpr fem::CellType T = decltype(tag)::value;
        const Eigen::Map<const fem::EdgeCoords<T>> x(X);
        const auto fe = mechanics::deadEdgeTraction<T>(x, traction, axisymmetric);
        scatter(c, fe.data());
      });
    }
  }
  for (const auto& bf : load.bodyForces) {
    auto force = [&](const Eigen::Vector2d& p) {
      return Eigen::Vector2d(loadValue(bf.fx, "FORCE_INTERNE", "FX", where, p(0), p(1), 0.0, t),
                             loadValue(bf.fy, "FORCE_INTERNE", "FY", where, p(0), p(1), 0.0, t));
    };
    for (int c : bf.cells) {
      where = " on cell " + mesh.cellName(c);
      gatherCoords(c, X);
      fem::dispatchSurface(fem::referenceCell(mesh.cellType(c), "loads"), [&](auto tag) {
        constexpr fem::CellType T = decltype(tag)::value;
        const Eigen::Map<const fem::NodeCoords<T>> x(X);
        const auto fe = mechanics::bodyForce<T>(x, force, axisymmetric);
        scatter(c, fe.data());
      });
    }
  }
  // FIXE_CSTE pressures: -int p N dS on the reference edge (the follower formula at u = 0).
  if (!applied.follower)
    for (const auto& pr : load.pressures) {
      if (pr.p.dependsOnCurrentPosition())
        throw Error("PRES_REP PRES depends on the current position (XF, YF, ZF): apply the load as a "
                    "follower load, EXCIT TYPE_CHARGE='SUIV'");
      auto pressure = [&](const Eigen::Vector2d& p) {
        return loadValue(pr.p, "PRES_REP", "PRES", where, p(0), p(1), 0.0, t);
      };
      for (int c : pr.cells) {
        where = " on cell " + mesh.cellName(c);
        gatherCoords(c, X);
        fem::dispatchEdge(fem::referenceCell(mesh.cellType(c), "loads"), [&](auto tag) {
          constexpr fem::CellType T = decltype(tag)::value;
          const Eigen::Map<const fem::EdgeCoords<T>> x(X);
          mechanics::EdgeVector<T> f;
          mechanics::followerPressure<T>(x, mechanics::EdgeVector<T>::Zero(), pressure, &f, nullptr, axisymmetric);
          scatter(c, f.data());
        });
      }
    }
  for (const auto& nf : load.nodalForces)
    for (int n : nf.nodes) {
      if (!dofs_.count(n)) continue;
      const Eigen::Vector3d p = mesh.node(n);
      where = " on node " + mesh.nodeName(n);
      F(dofs_.dof(n, 0)) += loadValue(nf.fx, "FORCE_NODALE", "FX", where, p(0), p(1), p(2), t);
      F(dofs_.dof(n, 1)) += loadValue(nf.fy, "FORCE_NODALE", "FY", where, p(0), p(1), p(2), t);
    }
  return F;
}

void MechanicalSystem::addDeadLoads(double t, Eigen::VectorXd& fext) const {
  for (std::size_t i = 0; i < problem_.loads.size(); ++i) {
    const double factor = problem_.loads[i].factor(t);
    if (constantDeadLoads_[i].size())
      fext += factor * constantDeadLoads_[i];
    else
      fext += factor * deadLoadVector(problem_.loads[i], t);
  }
}

void MechanicalSystem::internalForces(const Eigen::VectorXd& U, Eigen::VectorXd& fint) const {
  assembleCells(U, acceptedTime_, fint, nullptr, nullptr);
}

void MechanicalSystem::assembleCells(const Eigen::VectorXd& U, double t, Eigen::VectorXd& fint,
                                     const fem::AssemblyPattern* pattern, linalg::SparseMatrix* K,
                                     bool naturalState) const {
  fint.setZero(dofCount());
  // Element kernels on every thread, colour after colour (the kernels are pure functions
  // of fixed-size arrays: no allocation, no Lua); loads below stay serial.
  // Small models (the studies, the tests) keep the cells' order: same sums as ever.
  double* const f = fint.data();
  double* const values = K ? K->valuePtr() : nullptr;
  // The laws' new internal variables are not kept: acceptState() recomputes them.
  auto element = [&](const Cell& cell, double* X, double* u, double* un, double* variables, double* fe, double* Ke) {
    gatherCoords(cell.meshCell, X);
    const int n = cell.kernel->nodes();
    const int* d = elements_.dofs(cell.element);
    for (int i = 0; i < 2 * n; ++i) u[i] = U(d[i]);
    cell.kernel->internalForce(X, u, historyOf(cell, un, t, naturalState), variables, fe, values ? Ke : nullptr);
    for (int i = 0; i < 2 * n; ++i) f[d[i]] += fe[i];
    if (values) pattern->addMatrix(cell.element, Ke, values);
  };
  const std::int64_t nonZeros = K ? K->nonZeros() : 0;
  if (chunkColours_.empty()) {
    std::fill(values, values + nonZeros, 0.0);
    double X[2 * kMaxNodes], u[2 * kMaxNodes], un[2 * kMaxNodes], fe[2 * kMaxNodes], Ke[4 * kMaxNodes * kMaxNodes];
    std::vector<double> variables(kMaxGaussPoints * maxVariables_);
    try {
      for (const Cell& cell : cells_) element(cell, X, u, un, variables.data(), fe, Ke);
    } catch (const Error& e) {
      throw InvalidStateError(e.what());
    }
  } else {
    // Chunks of one colour share no unknown: the pool's threads claim them as they come
    // free. A kernel may throw (an inverted cell during a diverging Newton): the first
    // exception is thrown after the loop, for the step to be cut as in the serial case.
    WorkerPool& pool = WorkerPool::shared();
    constexpr std::int64_t kSlice = 1 << 16;
    pool.forEach(static_cast<int>((nonZeros + kSlice - 1) / kSlice), [&](int k) {
      const std::int64_t first = k * kSlice;
      std::fill(values + first, values + std::min(nonZeros, first + kSlice), 0.0);
    });
    const int cellCount = static_cast<int>(cells_.size());
    try {
      for (const std::vector<int>& colour : chunkColours_)
        pool.forEach(static_cast<int>(colour.size()), [&](int k) {
          double X[2 * kMaxNodes], u[2 * kMaxNodes], un[2 * kMaxNodes], fe[2 * kMaxNodes],
              Ke[4 * kMaxNodes * kMaxNodes];
          std::vector<double> variables(kMaxGaussPoints * maxVariables_);
          const int first = colour[k] * kChunkCells;
          for (int c = first; c < std::min(cellCount, first + kChunkCells); ++c)
            element(cells_[c], X, u, un, variables.data(), fe, Ke);
        });
    } catch (const Error& e) {
      throw InvalidStateError(e.what());
    }
  }
}

void MechanicalSystem::evaluate(const Eigen::VectorXd& U, double t, Eigen::VectorXd& fint, Eigen::VectorXd& fext,
                                const fem::AssemblyPattern* pattern, linalg::SparseMatrix* K, bool naturalState) const {
  assembleCells(U, t, fint, pattern, K, naturalState);
  fext.setZero(dofCount());
  double X[2 * kMaxNodes];
  addDeadLoads(t, fext);
  const bool axisymmetric = problem_.model->axisymmetric();
  const mesh::Mesh& mesh = problem_.model->mesh();
  for (const Edge& e : pressureEdges_) {
    gatherCoords(e.meshCell, X);
    const double factor = e.load->factor(t);
    const int* d = elements_.dofs(e.element);
    const std::string where = " on cell " + mesh.cellName(e.meshCell);
    auto pressure = [&](const Eigen::Vector2d& p) {
      return factor * loadValue(*e.p, "PRES_REP", "PRES", where, p(0), p(1), 0.0, t);
    };
    // A pressure of the current position (XF, YF) and its gradient there.
    auto pressureAtCurrent = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& current,
                                 Eigen::Vector2d* gradient) {
      try {
        const double value = e.p->atCurrentPosition(p(0), p(1), t, current(0), current(1), gradient->data());
        *gradient *= factor;
        return factor * value;
      } catch (const Error& failure) {
        throw Error("PRES_REP PRES" + where + " at XF = " + format::shortest(current(0)) +
                    ", YF = " + format::shortest(current(1)) + ", INST = " + format::shortest(t) + ": " +
                    failure.what());
      }
    };
    fem::dispatchEdge(fem::referenceCell(mesh.cellType(e.meshCell), "loads"), [&](auto tag) {
      constexpr fem::CellType T = decltype(tag)::value;
      constexpr int nd = 2 * fem::Cell<T>::nodes;
      const Eigen::Map<const fem::EdgeCoords<T>> x(X);
      mechanics::EdgeVector<T> ue, f;
      mechanics::EdgeMatrix<T> dfdu;
      for (int i = 0; i < nd; ++i) ue(i) = U(d[i]);
      if (e.p->dependsOnCurrentPosition())
        mechanics::followerPressure<T>(x, ue, pressureAtCurrent, &f, K ? &dfdu : nullptr, axisymmetric);
      else
        mechanics::followerPressure<T>(x, ue, pressure, &f, K ? &dfdu : nullptr, axisymmetric);
      for (int i = 0; i < nd; ++i) fext(d[i]) += f(i);
      if (K) {
        mechanics::EdgeMatrix<T> minus = -dfdu;
        pattern->addMatrix(e.element, minus.data(), K->valuePtr());
      }
    });
  }
}

std::vector<std::pair<int, double>> MechanicalSystem::imposed(double t) const {
  const mesh::Mesh& mesh = problem_.model->mesh();
  std::vector<int> slot(dofCount(), -1);
  std::vector<std::pair<int, double>> out;
  for (const auto& applied : problem_.loads) {
    const double factor = applied.factor(t);
    for (const auto& im : applied.load->imposed)
      for (int n : im.nodes) {
        const int d = dof(n, im.component);
        if (d < 0) throw Error("imposed displacement on node " + mesh.nodeName(n) + ", which carries no DOF");
        const Eigen::Vector3d p = mesh.node(n);
        const double v = factor * loadValue(im.value, "DDL_IMPO", im.component == 0 ? "DX" : "DY",
                                            " on node " + mesh.nodeName(n), p(0), p(1), p(2), t);
        if (slot[d] >= 0) {
          out[slot[d]].second = v;
        } else {
          slot[d] = static_cast<int>(out.size());
          out.emplace_back(d, v);
        }
      }
  }
  return out;
}

std::vector<int> MechanicalSystem::dualizedImposed() const {
  std::vector<char> dualized(dofCount(), 0), kinematic(dofCount(), 0);
  for (const auto& applied : problem_.loads)
    for (const auto& im : applied.load->imposed)
      for (int n : im.nodes) {
        const int d = dof(n, im.component);
        if (d >= 0) (applied.load->kinematic ? kinematic : dualized)[d] = 1;
      }
  std::vector<int> out;
  for (int d = 0; d < dofCount(); ++d)
    if (dualized[d] && !kinematic[d]) out.push_back(d);
  return out;
}

std::vector<linalg::LinearRelation> MechanicalSystem::linearRelations(double t) const {
  const mesh::Mesh& mesh = problem_.model->mesh();
  std::vector<linalg::LinearRelation> out;
  out.reserve(relationOrigins_.size());
  for (const auto& applied : problem_.loads) {
    if (applied.load->relations.empty()) continue;
    const double factor = applied.factor(t);
    for (const auto& rel : applied.load->relations) {
      linalg::LinearRelation r;
      for (const auto& term : rel.terms) r.terms.emplace_back(dof(term.node, term.component), term.coefficient);
      const int n = rel.terms.front().node;
      const Eigen::Vector3d p = mesh.node(n);
      r.rhs = factor * loadValue(rel.value, rel.origin.c_str(), "", " at node " + mesh.nodeName(n), p(0), p(1),
                                 p(2), t);
      out.push_back(std::move(r));
    }
  }
  return out;
}

linalg::ConstraintElimination MechanicalSystem::eliminate(const std::vector<char>& fixed,
                                                          const Eigen::VectorXd& values, double t) const {
  try {
    return linalg::ConstraintElimination(static_cast<int>(fixed.size()), fixed, values, linearRelations(t));
  } catch (const linalg::ContradictoryRelationError& e) {
    throw Error(relationOrigin(e.relation()) + ": this linear relation contradicts the imposed displacements and "
                "the relations before it (its two sides differ by " + format::shortest(e.mismatch()) +
                " at INST = " + format::shortest(t) + ")");
  }
}

mechanics::ElementHistory MechanicalSystem::historyOf(const Cell& cell, double* un, double t, bool natural) const {
  if (cell.state < 0) return {};
  if (natural) return {nullptr, nullptr, naturalVariables_.data()};
  const int* d = elements_.dofs(cell.element);
  for (int i = 0; i < 2 * cell.kernel->nodes(); ++i) un[i] = acceptedU_(d[i]);
  return {un, acceptedStress_.data() + 4 * cell.state, acceptedVariables_.data() + cell.variables, t,
          t - acceptedTime_};
}

void MechanicalSystem::acceptState(const Eigen::VectorXd& U, double t) {
  if (!hasHistory_) return;
  std::vector<double> stress(acceptedStress_.size()), variables(acceptedVariables_.size());
  double X[2 * kMaxNodes], u[2 * kMaxNodes], un[2 * kMaxNodes];
  try {
    for (const Cell& cell : cells_) {
      if (cell.state < 0) continue;
      gatherCoords(cell.meshCell, X);
      const int* d = elements_.dofs(cell.element);
      for (int i = 0; i < 2 * cell.kernel->nodes(); ++i) u[i] = U(d[i]);
      cell.kernel->stresses(X, u, historyOf(cell, un, t), stress.data() + 4 * cell.state,
                            variables.data() + cell.variables, false);
    }
  } catch (const Error& e) {
    throw InvalidStateError(e.what());
  }
  acceptedU_ = U.head(dofCount());
  acceptedTime_ = t;
  acceptedStress_.swap(stress);
  acceptedVariables_.swap(variables);
}

void MechanicalSystem::setAcceptedState(const Eigen::VectorXd& U, const std::vector<double>* stresses,
                                        const std::vector<double>* variables) {
  if (!hasHistory_) return;
  acceptedU_ = U.head(dofCount());
  std::fill(acceptedStress_.begin(), acceptedStress_.end(), 0.0);
  std::fill(acceptedVariables_.begin(), acceptedVariables_.end(), 0.0);
  std::size_t stressCount = 0, variableCount = 0;
  for (const Cell& cell : cells_) {
    stressCount += 4 * cell.kernel->gaussPoints();
    variableCount += static_cast<std::size_t>(cell.kernel->gaussPoints()) * maxVariables_;
  }
  if ((stresses && stresses->size() != stressCount) || (variables && variables->size() != variableCount))
    throw Error("internal error: the initial stresses or internal variables do not match the model's Gauss points");
  std::size_t stressAt = 0, variableAt = 0;
  for (const Cell& cell : cells_) {
    const int points = cell.kernel->gaussPoints(), count = cell.kernel->internalVariables();
    if (cell.state >= 0) {
      if (stresses)
        std::copy(stresses->begin() + stressAt, stresses->begin() + stressAt + 4 * points,
                  acceptedStress_.begin() + 4 * cell.state);
      if (variables)
        for (int q = 0; q < points; ++q)
          for (int v = 0; v < count; ++v)
            acceptedVariables_[cell.variables + q * count + v] = (*variables)[variableAt + q * maxVariables_ + v];
    }
    stressAt += 4 * points;
    variableAt += static_cast<std::size_t>(points) * maxVariables_;
  }
}

void MechanicalSystem::gaussStresses(const Eigen::VectorXd& U, std::vector<int>& offsets,
                                     std::vector<double>& values) const {
  offsets.assign(1, 0);
  values.clear();
  double X[2 * kMaxNodes], u[2 * kMaxNodes], un[2 * kMaxNodes];
  std::vector<double> s, variables(kMaxGaussPoints * maxVariables_);
  for (const Cell& cell : cells_) {
    gatherCoords(cell.meshCell, X);
    const int* d = elements_.dofs(cell.element);
    for (int i = 0; i < 2 * cell.kernel->nodes(); ++i) u[i] = U(d[i]);
    s.resize(4 * cell.kernel->gaussPoints());
    cell.kernel->stresses(X, u, historyOf(cell, un, acceptedTime_), s.data(), variables.data(), true);
    values.insert(values.end(), s.begin(), s.end());
    offsets.push_back(static_cast<int>(values.size()));
  }
}

std::vector<std::string> MechanicalSystem::internalVariableNames() const {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < problem_.relations.size(); ++k) {
    const auto& law = problem_.relations[k];
    if (!law || cells_[k].kernel->internalVariables() == 0) continue;
    std::vector<std::string> own = law->internalVariableNames();
    // GDEF_LOG's element adds the stress tau after the law's own variables.
    if (problem_.kinematics[k] == mechanics::Kinematics::Logarithmic)
      for (const char* t : {"TXX", "TYY", "TZZ", "TXY", "TXZ", "TYZ"}) own.push_back(t);
    if (names.empty()) names = own;
    else if (own != names) return {};
  }
  return names;
}

void MechanicalSystem::gaussVariables(std::vector<int>& offsets, std::vector<double>& values) const {
  offsets.assign(1, 0);
  values.clear();
  for (const Cell& cell : cells_) {
    const int points = cell.kernel->gaussPoints(), count = cell.kernel->internalVariables();
    for (int q = 0; q < points; ++q)
      for (int v = 0; v < maxVariables_; ++v)
        values.push_back(cell.state >= 0 && v < count ? acceptedVariables_[cell.variables + q * count + v] : 0.0);
    offsets.push_back(static_cast<int>(values.size()));
  }
}

void MechanicalSystem::gaussGeometry(std::vector<int>& offsets, std::vector<double>& xy,
                                     std::vector<double>& weights) const {
  offsets.assign(1, 0);
  xy.clear();
  weights.clear();
  double X[2 * kMaxNodes];
  for (const Cell& cell : cells_) {
    gatherCoords(cell.meshCell, X);
    const int q = cell.kernel->gaussPoints();
    const std::size_t w0 = weights.size();
    xy.resize(xy.size() + 2 * q);
    weights.resize(w0 + q);
    cell.kernel->gaussGeometry(X, xy.data() + 2 * w0, weights.data() + w0);
    offsets.push_back(static_cast<int>(weights.size()));
  }
}

std::string MechanicalSystem::unknownName(int dof) const {
  for (int node = 0; node < dofs_.nodeCount(); ++node)
    if (dofs_.count(node) && dof >= dofs_.first(node) && dof < dofs_.first(node) + dofs_.count(node))
      return std::string("unknown ") + (dof == dofs_.first(node) ? "DX" : "DY") + " of node " +
             problem_.model->mesh().nodeName(node);
  return "";
}

}  // namespace aster::analysis
