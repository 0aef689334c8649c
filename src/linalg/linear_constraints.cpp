#include "linalg/linear_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace aster::linalg {

ConstraintElimination::ConstraintElimination(int n, const std::vector<char>& fixed, const Eigen::VectorXd& values,
                                             const std::vector<LinearRelation>& relations)
    : n_(n), constrained_(n, 0), slaveRow_(n, -1), g_(Eigen::VectorXd::Zero(n)) {
  for (int i = 0; i < n; ++i)
    if (!fixed.empty() && fixed[i]) {
      constrained_[i] = 1;
      g_(i) = values(i);
    }
  // The relation being reduced, scattered: its coefficient per unknown, and its
  // unknowns in the order they came (the first of equal pivots wins).
  std::vector<double> acc(n, 0.0);
  std::vector<char> listed(n, 0);
  std::vector<int> order;
  // Per master: the slaves whose expression holds it (to substitute it when it becomes a slave).
  std::unordered_map<int, std::vector<int>> users;
  for (std::size_t k = 0; k < relations.size(); ++k) {
    const LinearRelation& rel = relations[k];
    order.clear();
    double b = rel.rhs, size = std::fabs(rel.rhs), coefScale = 0;
    auto add = [&](int j, double a) {
      if (!listed[j]) {
        listed[j] = 1;
        order.push_back(j);
      }
      acc[j] += a;
      coefScale = std::max(coefScale, std::fabs(a));
    };
    for (const auto& [j, a] : rel.terms) {
      if (j < 0 || j >= n) throw Error("internal error: a linear relation names unknown " + std::to_string(j));
      if (constrained_[j] && slaveRow_[j] < 0) {
        b -= a * g_(j);
        size += std::fabs(a * g_(j));
      } else if (slaveRow_[j] >= 0) {
        const Slave& s = slaves_[slaveRow_[j]];
        for (const auto& [m, c] : s.masters) add(m, a * c);
        b -= a * s.constant;
        size += std::fabs(a * s.constant);
      } else {
        add(j, a);
      }
    }
    // A coefficient that cancelled (to round-off of the ones added) is no pivot. The pivot
    // is the first unknown whose coefficient is at least half the largest (threshold
    // pivoting): the relation's own unknown, given first, becomes the slave, and the
    // unknowns several relations share (a LIAISON_UNIF's first node, a solid's A and B)
    // stay masters, which keeps the slaves' expressions short.
    const double drop = 1e-12 * coefScale;
    double largest = 0;
    for (int j : order) largest = std::max(largest, std::fabs(acc[j]));
    int pivot = -1;
    if (largest > drop)
      for (int j : order)
        if (std::fabs(acc[j]) >= 0.5 * largest) {
          pivot = j;
          break;
        }
    if (pivot < 0) {
      for (int j : order) acc[j] = 0, listed[j] = 0;
      if (std::fabs(b) <= 1e-10 * size) {
        ++redundant_;
        continue;
      }
      throw ContradictoryRelationError("linear relation " + std::to_string(k + 1) +
                                           " contradicts the fixed values and the relations before it (its sides "
                                           "differ by " + std::to_string(b) + ")",
                                       static_cast<int>(k), b);
    }
    Slave s{pivot, {}, b / acc[pivot]};
    for (int j : order)
      if (j != pivot && std::fabs(acc[j]) > drop) s.masters.emplace_back(j, -acc[j] / acc[pivot]);
    for (int j : order) acc[j] = 0, listed[j] = 0;
    const int row = static_cast<int>(slaves_.size());
    // The slaves defined so far hold masters only: substitute the new slave in those that hold it.
    if (auto it = users.find(pivot); it != users.end()) {
      for (int r : it->second) {
        Slave& t = slaves_[r];
        auto at = std::find_if(t.masters.begin(), t.masters.end(), [&](const auto& e) { return e.first == pivot; });
        if (at == t.masters.end()) continue;
        const double w = at->second;
        t.masters.erase(at);
        t.constant += w * s.constant;
        for (const auto& [m, c] : s.masters) {
          auto same = std::find_if(t.masters.begin(), t.masters.end(), [&](const auto& e) { return e.first == m; });
          if (same != t.masters.end()) {
            same->second += w * c;
          } else {
            t.masters.emplace_back(m, w * c);
            users[m].push_back(r);
          }
        }
      }
      users.erase(pivot);
    }
    for (const auto& mc : s.masters) users[mc.first].push_back(row);
    slaveRow_[pivot] = row;
    constrained_[pivot] = 1;
    slaves_.push_back(std::move(s));
  }
  for (const Slave& s : slaves_) g_(s.unknown) = s.constant;
  buildTransformation();
}

void ConstraintElimination::buildTransformation() {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(n_);
  for (int i = 0; i < n_; ++i)
    if (!constrained_[i]) entries.emplace_back(i, i, 1.0);
  for (const Slave& s : slaves_)
    for (const auto& [m, c] : s.masters) entries.emplace_back(s.unknown, m, c);
  T_.resize(n_, n_);
  T_.setFromTriplets(entries.begin(), entries.end());
  T_.makeCompressed();
  Tt_ = T_.transpose();
  Tt_.makeCompressed();
}

bool ConstraintElimination::sameTransformation(const ConstraintElimination& other) const {
  if (n_ != other.n_ || constrained_ != other.constrained_ || slaves_.size() != other.slaves_.size()) return false;
  for (std::size_t k = 0; k < slaves_.size(); ++k)
    if (slaves_[k].unknown != other.slaves_[k].unknown || slaves_[k].masters != other.slaves_[k].masters)
      return false;
  return true;
}

SparseMatrix ConstraintElimination::reduce(const SparseMatrix& K) const {
  const SparseMatrix KT = K * T_;
  SparseMatrix A = Tt_ * KT;
  // The two triangles of T^T K T differ by round-off: their mean is exactly symmetric.
  const SparseMatrix At = A.transpose();
  A = 0.5 * (A + At);
  std::vector<Eigen::Triplet<double, int>> ones;
  for (int i = 0; i < n_; ++i)
    if (constrained_[i]) ones.emplace_back(i, i, 1.0);
  SparseMatrix D(n_, n_);
  D.setFromTriplets(ones.begin(), ones.end());
  A = A + D;
  A.makeCompressed();
  return A;
}

Eigen::VectorXd ConstraintElimination::reduce(const Eigen::VectorXd& f) const { return Tt_ * f; }

Eigen::VectorXd ConstraintElimination::expand(const Eigen::VectorXd& v) const { return T_ * v + g_; }

}  // namespace aster::linalg
