#include "analysis/low_rank_update.hpp"

#include <algorithm>

#include <Eigen/LU>

namespace aster::analysis {

LowRankUpdate::LowRankUpdate(const linalg::LinearSolver& solver, const linalg::SparseMatrix& M,
                             const std::vector<char>& fixed, const Eigen::VectorXd& b, const Eigen::VectorXd& x0,
                             std::vector<int> rows)
    : solver_(solver), M_(M), fixed_(fixed), b_(b), x0_(x0), rows_(std::move(rows)), at_(M.rows(), -1) {
  for (std::size_t r = 0; r < rows_.size(); ++r) at_[rows_[r]] = static_cast<int>(r);
}

// Row i of M, from its column's pattern (the pattern is structurally symmetric).
LowRankUpdate::Sparse LowRankUpdate::oldRow(int i) const {
  Sparse row;
  const int* outer = M_.outerIndexPtr();
  const int* rows = M_.innerIndexPtr();
  const double* values = M_.valuePtr();
  for (int p = outer[i]; p < outer[i + 1]; ++p) {
    const int j = rows[p];
    const int* begin = rows + outer[j];
    const int* end = rows + outer[j + 1];
    const int* at = std::lower_bound(begin, end, i);
    if (at != end && *at == i && values[at - rows] != 0) row.push_back({j, values[at - rows]});
  }
  return row;
}

// Unknown i's row and column hold their diagonal only: M^-1 e_i = e_i / M_ii.
bool LowRankUpdate::decoupled(int i) const {
  for (linalg::SparseMatrix::InnerIterator e(M_, i); e; ++e)
    if (e.row() != i && e.value() != 0) return false;
  for (const auto& [j, a] : oldRow(i))
    if (j != i) return false;
  return M_.coeff(i, i) != 0;
}

// M^-1 u on the kept rows, for each (key, u) not kept yet: one solve with as many
// right-hand sides, which reads the factor once.
void LowRankUpdate::inverseTimes(const std::vector<std::pair<int, Sparse>>& columns) {
  std::vector<const std::pair<int, Sparse>*> missing;
  for (const auto& c : columns)
    if (!kept_.count(c.first)) missing.push_back(&c);
  if (missing.empty()) return;
  const Eigen::Index k = static_cast<Eigen::Index>(missing.size());
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(M_.rows(), k), z;
  for (Eigen::Index c = 0; c < k; ++c)
    for (const auto& [j, a] : missing[c]->second) rhs(j, c) += a;
  solver_.solveMany(rhs, z);
  solves_ += static_cast<int>(k);
  for (Eigen::Index c = 0; c < k; ++c) {
    Eigen::VectorXd kept(static_cast<Eigen::Index>(rows_.size()));
    for (std::size_t r = 0; r < rows_.size(); ++r) kept(static_cast<Eigen::Index>(r)) = z(rows_[r], c);
    kept_.emplace(missing[c]->first, std::move(kept));
  }
}

// The new row of a change, the fixed unknowns' terms left out (they go to the right-hand
// side with their values x0, as the solve did).
std::map<int, double> LowRankUpdate::freeRow(const AdditionalTerms::StatusChange& c) const {
  std::map<int, double> row;
  for (const auto& [j, a] : c.row)
    if (!fixed_[j]) row[j] += a;
  return row;
}

// A symmetric change's column off the diagonal: new (the row's) minus old.
LowRankUpdate::Sparse LowRankUpdate::columnChange(int i, const std::map<int, double>& row) const {
  std::map<int, double> u;
  for (const auto& [j, a] : row)
    if (j != i) u[j] += a;
  for (linalg::SparseMatrix::InnerIterator e(M_, i); e; ++e)
    if (e.row() != i) u[e.row()] -= e.value();
  Sparse us;
  for (const auto& [j, a] : u)
    if (a != 0) us.push_back({j, a});
  return us;
}

int LowRankUpdate::solvesNeeded(const std::vector<AdditionalTerms::StatusChange>& changes) const {
  int n = 0;
  for (const auto& c : changes) {
    if (!kept_.count(2 * c.unknown) && !decoupled(c.unknown)) ++n;
    if (c.symmetric && !kept_.count(2 * c.unknown + 1)) ++n;
  }
  return n;
}

bool LowRankUpdate::solve(const std::vector<AdditionalTerms::StatusChange>& changes, Eigen::VectorXd& x, bool full) {
  // Z's columns on the kept rows: M^-1 u, or e_i / M_ii.
  struct Column {
    const Eigen::VectorXd* kept = nullptr;
    int unit = -1;  // a row of rows_
    double scale = 0;
    double at(int r) const { return kept ? (*kept)(r) : r == unit ? scale : 0.0; }
    void addTo(Eigen::VectorXd& y, double a) const {
      if (kept) y += a * *kept;
      else y(unit) += a * scale;
    }
  };
  std::vector<Sparse> U, V;  // U on every row, V on the kept rows
  std::vector<Column> Z;
  // b' - b, and y = M^-1 b' on the kept rows.
  Sparse db;
  Eigen::VectorXd y(static_cast<Eigen::Index>(rows_.size()));
  for (std::size_t r = 0; r < rows_.size(); ++r) y(static_cast<Eigen::Index>(r)) = x0_(rows_[r]);
  auto kept = [&](const Sparse& s) {
    Sparse out;
    for (const auto& [j, a] : s) {
      if (at_[j] < 0) throw std::logic_error("LowRankUpdate: a change outside the kept rows");
      out.push_back({at_[j], a});
    }
    return out;
  };
  // Every solve this call needs, at once; the symmetric changes' columns kept for below.
  std::vector<std::pair<int, Sparse>> needed;
  std::vector<Sparse> columns(changes.size());
  for (std::size_t k = 0; k < changes.size(); ++k) {
    const auto& c = changes[k];
    if (!decoupled(c.unknown)) needed.push_back({2 * c.unknown, {{c.unknown, 1.0}}});
    if (!c.symmetric) continue;
    columns[k] = columnChange(c.unknown, freeRow(c));
    if (!columns[k].empty()) needed.push_back({2 * c.unknown + 1, columns[k]});
  }
  inverseTimes(needed);
  for (std::size_t k = 0; k < changes.size(); ++k) {
    const auto& c = changes[k];
    const int i = c.unknown;
    const std::map<int, double> row = freeRow(c);
    double rhs = c.rhs;
    for (const auto& [j, a] : c.row)
      if (fixed_[j]) rhs -= a * x0_(j);
    std::map<int, double> v = row;
    for (const auto& [j, a] : oldRow(i)) v[j] -= a;
    Column ei;
    if (decoupled(i)) {
      ei.unit = at_[i];
      ei.scale = 1.0 / M_.coeff(i, i);
    } else {
      ei.kept = &kept_.at(2 * i);
    }
    ei.addTo(y, rhs - b_(i));
    db.push_back({i, rhs - b_(i)});
    U.push_back({{i, 1.0}});
    V.push_back(kept(Sparse(v.begin(), v.end())));
    Z.push_back(ei);
    if (!c.symmetric) continue;
    const Sparse& us = columns[k];
    if (us.empty()) continue;
    Column col;
    col.kept = &kept_.at(2 * i + 1);
    U.push_back(us);
    V.push_back(kept({{i, 1.0}}));
    Z.push_back(col);
  }
  const int p = static_cast<int>(V.size());
  Eigen::MatrixXd C = Eigen::MatrixXd::Identity(p, p);
  Eigen::VectorXd Vy = Eigen::VectorXd::Zero(p);
  for (int a = 0; a < p; ++a)
    for (const auto& [r, val] : V[a]) {
      Vy(a) += val * y(r);
      for (int c = 0; c < p; ++c) C(a, c) += val * Z[c].at(r);
    }
  Eigen::VectorXd w(p);  // no change: w is empty and x is M^-1 b'
  if (p > 0) {
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(C);
    if (!lu.isInvertible()) return false;
    w = lu.solve(Vy);
  }
  if (full) {
    // x = M^-1 (b' - U w): one more solve.
    Eigen::VectorXd rhs = b_;
    for (const auto& [j, a] : db) rhs(j) += a;
    for (int c = 0; c < p; ++c)
      for (const auto& [j, a] : U[c]) rhs(j) -= w(c) * a;
    solver_.solve(rhs, x);
    ++solves_;
  } else {
    for (int c = 0; c < p; ++c) Z[c].addTo(y, -w(c));
    x = x0_;
    for (std::size_t r = 0; r < rows_.size(); ++r) x(rows_[r]) = y(static_cast<Eigen::Index>(r));
  }
  return x.allFinite();
}

}  // namespace aster::analysis
