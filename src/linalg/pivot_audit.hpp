// Singularity diagnosis shared by the solvers: after a numeric factorization, each pivot
// is compared with the matrix entry it started from (code_aster's NPREC criterion).
#pragma once
#include <cmath>
#include <string>

#include "linalg/linear_solver.hpp"

namespace aster::linalg {

struct Pivot {
  double value;     // pivot (U(k,k) of the possibly scaled matrix, or D(k,k) for symmetric factorizations)
  double original;  // the entry of the same (scaled) matrix at the pivot's position before elimination
  int row;          // original row index of the pivot
  int column;       // original column index of the pivot
};

// Throws SingularMatrixError naming the column of a zero pivot.
[[noreturn]] void throwZeroPivot(const std::string& method, int column, int row, const std::string& detail = "");

// Checks every pivot: zero -> singular; more than nprec digits lost -> numerically singular
// (nprec <= 0 disables the second test). pivotAt(k) returns the k-th Pivot.
template <class PivotAt>
void auditPivots(const std::string& method, int n, int nprec, PivotAt&& pivotAt);

// Implementation detail of auditPivots: the error for a pivot that lost too many digits.
[[noreturn]] void throwLostDigits(const std::string& method, const Pivot& p, double digits, int nprec);

template <class PivotAt>
void auditPivots(const std::string& method, int n, int nprec, PivotAt&& pivotAt) {
  const double ratioLimit = nprec > 0 ? std::pow(10.0, -nprec) : 0.0;
  for (int k = 0; k < n; ++k) {
    const Pivot p = pivotAt(k);
    if (p.value == 0.0 || !std::isfinite(p.value)) throwZeroPivot(method, p.column, p.row);
    if (ratioLimit > 0.0 && p.original != 0.0 && std::abs(p.value) < ratioLimit * std::abs(p.original))
      throwLostDigits(method, p, std::log10(std::abs(p.original) / std::abs(p.value)), nprec);
  }
}

}  // namespace aster::linalg
