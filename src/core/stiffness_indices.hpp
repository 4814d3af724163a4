// Stiffness performance indices of a symmetric matrix: Gonçalves et al. 2010, section 3, eq. (7)-(13).
#pragma once

#include <string>

#include "core/types.hpp"

namespace kinestat {

struct StiffnessIndices {
  int size = 0;
  // Determinant, eq. (7). The determinant of a 36x36 stiffness matrix is ~1e250 and overflows
  // easily, so its sign and log10 of its magnitude are kept; `determinant` is +-inf on overflow.
  int det_sign = 0;
  double log10_abs_det = 0.0;
  double determinant = 0.0;
  double trace = 0.0;           // eq. (8)
  double norm_1 = 0.0;          // eq. (9): max column sum of |k_ij|
  double norm_2 = 0.0;          // eq. (10): spectral norm, max |eigenvalue|
  double norm_frobenius = 0.0;  // eq. (11)
  double norm_inf = 0.0;        // induced infinity-norm: max row sum of |k_ij| (the paper's "Chebyshev" column)
  double max_abs_entry = 0.0;   // eq. (12) as printed: max |k_ij|
  double condition_number = 0.0;  // eq. (13) with the 2-norm: max|eig| / min|eig| (inf if singular)
  VecX eigenvalues;             // ascending
  MatX eigenvectors;            // columns, unit length, matching `eigenvalues`
  double symmetry_error = 0.0;  // ||K - K^T||_F / ||K||_F (the indices assume symmetry)
};

// Computes every index of K (dense, symmetric). The eigen-decomposition is of the symmetric part.
StiffnessIndices stiffness_indices(const MatX& K);

}  // namespace kinestat
