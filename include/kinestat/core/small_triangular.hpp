// Forward substitution with a small lower triangle for the per-posture kernels (the VJM's regular
// stiffness, vjm/stiffness.cpp; the fixed-size kernels, mechanisms/fixed_size_vjm.hpp): Eigen's
// triangular solve takes its blocked path (GEMM packing) at dynamic sizes, 8 % of the Delta file's
// map at a chain's dozen springs and six columns.
#pragma once

#include <Eigen/Core>

namespace kinestat {

// B := L^-1 B for the lower triangle of L's top-left B.rows() x B.rows() block (the entries above its
// diagonal are not read), by rows in plain loops; zero entries of L are skipped (a chain's spring
// stiffness is block diagonal, and so is its Cholesky factor).
template <class MatrixL, class MatrixB>
void lower_solve_in_place(const MatrixL& L, MatrixB& B) {
  for (Eigen::Index i = 0; i < B.rows(); ++i) {
    for (Eigen::Index k = 0; k < i; ++k) {
      const double l = L(i, k);
      if (l != 0.0) B.row(i) -= l * B.row(k);
    }
    B.row(i) /= L(i, i);
  }
}

}  // namespace kinestat
