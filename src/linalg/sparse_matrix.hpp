// The program's one sparse matrix type: compressed sparse columns of doubles
// with int indices, the layout CHOLMOD, UMFPACK and KLU read without a copy.
#pragma once
#include <Eigen/SparseCore>

namespace aster::linalg {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace aster::linalg
