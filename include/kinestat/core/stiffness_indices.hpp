// Stiffness performance indices of a symmetric matrix: Gonçalves et al. 2010, section 3, eq. (7)-(13).
#pragma once

#include <string>

#include "kinestat/core/types.hpp"

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

// The indices as printed lines (reports of every method).
std::string indices_report(const StiffnessIndices& ix);

// The same indices of a 6x6 Cartesian stiffness (dofs ux uy uz rx ry rz) for posture sweeps: fixed
// size, no heap allocation, plus the eigenvalues of the translational and rotational 3x3 blocks
// (the stiffness in the weakest and strongest direction of translation and of rotation).
// Equal to stiffness_indices(K) on the common fields (tests). Units: K in N/m, N, N m/rad.
struct CartesianIndices {
  int det_sign = 0;
  double log10_abs_det = 0.0;
  double trace = 0.0;
  double norm_1 = 0.0;
  double norm_2 = 0.0;
  double norm_frobenius = 0.0;
  double norm_inf = 0.0;
  double max_abs_entry = 0.0;
  double condition_number = 0.0;        // max|eig| / min|eig| of the 6x6 (inf if singular)
  Vec6 eigenvalues = Vec6::Zero();      // of the 6x6, ascending (mixed units)
  Vec3 translational_eigenvalues = Vec3::Zero();  // of K[0:3, 0:3], ascending, N/m
  Vec3 rotational_eigenvalues = Vec3::Zero();     // of K[3:6, 3:6], ascending, N m/rad
  double symmetry_error = 0.0;          // ||K - K^T||_F / ||K||_F
};
CartesianIndices cartesian_indices(const Mat6& K);

}  // namespace kinestat
