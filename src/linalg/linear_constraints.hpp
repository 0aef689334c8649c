// Linear relations between unknowns (sum_i a_i u_i = b) and fixed values
// (u_i = g_i), eliminated by a master-slave transformation that keeps a
// symmetric positive definite stiffness so: u = T v + g, where each slave
// unknown is a combination of free (master) unknowns plus a constant, and the
// reduced system is T^T K T v = T^T (f - K g). The slaves are chosen by a
// pivoted elimination of the relations taken in order (threshold pivoting: the
// first unknown of a relation whose coefficient is at least half the largest), so chained relations (u1 = u2, u2 = u3) and redundant ones (a
// relation that follows from the others) are accepted; a relation that
// contradicts the others throws ContradictoryRelationError.
//
// The reduced system keeps the size n: the rows and columns of the fixed and
// slave unknowns are identity rows (as eliminateFixedUnknowns makes them), so
// the unknowns keep their numbers for the solvers and their messages.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/error.hpp"
#include "linalg/sparse_matrix.hpp"

namespace aster::linalg {

struct LinearRelation {  // sum of coefficient * u[unknown] over terms = rhs
  std::vector<std::pair<int, double>> terms;
  double rhs = 0;
};

// The relation of index relation() (in the list given) contradicts the fixed
// values and the relations before it: its two sides differ by mismatch().
class ContradictoryRelationError : public Error {
 public:
  ContradictoryRelationError(const std::string& what, int relation, double mismatch)
      : Error(what), relation_(relation), mismatch_(mismatch) {}
  int relation() const { return relation_; }
  double mismatch() const { return mismatch_; }

 private:
  int relation_;
  double mismatch_;
};

class ConstraintElimination {
 public:
  ConstraintElimination() = default;
  // n unknowns; fixed[i]: u_i = values(i) (values may be empty when nothing is fixed).
  // Relations whose terms cancel after the elimination of those before them are
  // redundant when their right-hand sides agree to 1e-10 of their size, contradictory
  // otherwise (throws).
  ConstraintElimination(int n, const std::vector<char>& fixed, const Eigen::VectorXd& values,
                        const std::vector<LinearRelation>& relations);

  int size() const { return n_; }
  // Per unknown: fixed or slave (an identity row of the reduced matrix).
  const std::vector<char>& constrained() const { return constrained_; }
  bool isSlave(int i) const { return slaveRow_[i] >= 0; }
  int slaveCount() const { return static_cast<int>(slaves_.size()); }
  int redundantCount() const { return redundant_; }
  // Same T (same constrained unknowns, same slave coefficients): a factorization of
  // the other's reduced matrix serves this one.
  bool sameTransformation(const ConstraintElimination& other) const;

  // T^T K T, exactly symmetric, with identity rows and columns at the constrained
  // unknowns. The pattern depends only on K's pattern and on T's.
  SparseMatrix reduce(const SparseMatrix& K) const;
  // T^T f, zero at the constrained unknowns.
  Eigen::VectorXd reduce(const Eigen::VectorXd& f) const;
  // T v + g: every unknown from the masters of v (its constrained entries are ignored).
  Eigen::VectorXd expand(const Eigen::VectorXd& v) const;
  // g: the fixed values, and each slave's constant.
  const Eigen::VectorXd& offset() const { return g_; }

 private:
  void buildTransformation();

  int n_ = 0;
  int redundant_ = 0;
  std::vector<char> constrained_;
  std::vector<int> slaveRow_;  // per unknown: its row in slaves_, -1 when it is no slave
  struct Slave {
    int unknown;
    std::vector<std::pair<int, double>> masters;  // u_s = sum c_m u_m + constant
    double constant;
  };
  std::vector<Slave> slaves_;
  Eigen::VectorXd g_;
  SparseMatrix T_, Tt_;
};

}  // namespace aster::linalg
