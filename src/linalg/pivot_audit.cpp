#include "linalg/pivot_audit.hpp"

#include <sstream>

namespace aster::linalg {

namespace {
const char* const kFreeHint = "; the structure may be free to move (missing Dirichlet conditions?)";
}

void throwZeroPivot(const std::string& method, int column, int row, const std::string& detail) {
  std::ostringstream s;
  s << method << ": the matrix is singular: ";
  if (column >= 0) {
    s << "the pivot of column " << column;
    if (row >= 0 && row != column) s << " (pivot row " << row << ")";
    s << " is zero";
  } else {
    s << "a pivot is zero (the library does not say which)";
  }
  s << detail << kFreeHint;
  throw SingularMatrixError(s.str(), column, row);
}

void throwLostDigits(const std::string& method, const Pivot& p, double digits, int nprec) {
  std::ostringstream s;
  s.precision(3);
  s << method << ": the matrix is numerically singular: the pivot of column " << p.column;
  if (p.row != p.column) s << " (pivot row " << p.row << ")";
  s << " lost " << digits << " significant digits (pivot " << p.value << " against the entry " << p.original
    << " it started from), more than NPREC = " << nprec << kFreeHint << " or the matrix is very ill conditioned";
  throw SingularMatrixError(s.str(), p.column, p.row);
}

}  // namespace aster::linalg
