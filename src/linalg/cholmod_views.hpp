// aster-lite's data as CHOLMOD's structures and back, without copies: for the CHOLMOD
// solver and for the tests that hold its multifrontal factorization against CHOLMOD's.
#pragma once
#include <cholmod.h>

#include "linalg/linear_solver.hpp"
#include "linalg/multifrontal_cholesky.hpp"

namespace aster::linalg {

// A symmetric n x n matrix in compressed columns (int indices), its lower triangle read
// (stype = -1); no values (x null): its pattern only.
inline cholmod_sparse symmetricView(int n, const int* p, const int* i, const double* x) {
  cholmod_sparse s{};
  s.nrow = s.ncol = static_cast<size_t>(n);
  s.nzmax = static_cast<size_t>(p[n]);
  s.p = const_cast<int*>(p);
  s.i = const_cast<int*>(i);
  s.x = const_cast<double*>(x);
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = x ? CHOLMOD_REAL : CHOLMOD_PATTERN;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 0;
  s.packed = 1;
  return s;
}

// A (compressed), lower triangle read: saves the supernodal analysis one transpose over the
// upper one.
inline cholmod_sparse lowerView(const SparseMatrix& A) {
  return symmetricView(static_cast<int>(A.rows()), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr());
}

// The fields of a supernodal symbolic factor (int indices) the multifrontal factorization reads.
inline SupernodalStructure supernodalStructure(const cholmod_factor& L) {
  SupernodalStructure s;
  s.n = static_cast<int>(L.n);
  s.supernodeCount = static_cast<int>(L.nsuper);
  s.firstColumn = static_cast<const int*>(L.super);
  s.rowStart = static_cast<const int*>(L.pi);
  s.valueStart = static_cast<const int*>(L.px);
  s.rows = static_cast<const int*>(L.s);
  s.permutation = static_cast<const int*>(L.Perm);
  return s;
}

}  // namespace aster::linalg
