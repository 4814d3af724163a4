// Stiffness performance indices of a symmetric matrix: Gonçalves et al. 2010, section 3, eq. (7)-(13).
// One implementation over the matrix size: StiffnessIndices for any size (an MSA structure's whole
// K), CartesianIndices for a 6x6 tool-point stiffness (posture sweeps: fixed size, no heap).
#pragma once

#include <string>

#include "kinestat/core/types.hpp"

namespace kinestat {

// The indices every size has. N: the matrix's size, or Eigen::Dynamic.
template <int N>
struct MatrixIndices {
  using Vector = Eigen::Matrix<double, N, 1>;
  // Determinant, eq. (7). The determinant of a 36x36 stiffness matrix is ~1e250 and overflows
  // easily, so its sign and log10 of its magnitude are kept; `determinant` is +-inf on overflow.
  int det_sign = 0;
  double log10_abs_det = 0.0;
  double determinant = 0.0;
  double trace = 0.0;             // eq. (8)
  double norm_1 = 0.0;            // eq. (9): max column sum of |k_ij|
  double norm_2 = 0.0;            // eq. (10): spectral norm, max |eigenvalue|
  double norm_frobenius = 0.0;    // eq. (11)
  double norm_inf = 0.0;          // induced infinity-norm: max row sum of |k_ij| (the paper's "Chebyshev" column)
  double max_abs_entry = 0.0;     // eq. (12) as printed: max |k_ij|
  double condition_number = 0.0;  // eq. (13) with the 2-norm: max|eig| / min|eig| (inf if singular)
  Vector eigenvalues = Vector::Zero(N == Eigen::Dynamic ? 0 : N);  // of the symmetric part, ascending
  double symmetry_error = 0.0;  // ||K - K^T||_F / ||K||_F (the indices assume symmetry)
};

// Any size, with the eigenvectors (reports, JSON).
struct StiffnessIndices : MatrixIndices<Eigen::Dynamic> {
  int size = 0;
  MatX eigenvectors;  // columns, unit length, matching `eigenvalues`
};

// Computes every index of K (dense, symmetric). The eigen-decomposition is of the symmetric part.
StiffnessIndices stiffness_indices(const MatX& K);

// The indices as printed lines (reports of every method).
std::string indices_report(const StiffnessIndices& ix);

// A 6x6 Cartesian stiffness (dofs ux uy uz rx ry rz; K in N/m, N, N m/rad): no eigenvectors, plus
// the eigenvalues of the translational and rotational 3x3 blocks (the stiffness in the weakest and
// strongest direction of translation and of rotation). The 6x6's eigenvalues mix units.
struct CartesianIndices : MatrixIndices<6> {
  Vec3 translational_eigenvalues = Vec3::Zero();  // of K[0:3, 0:3], ascending, N/m
  Vec3 rotational_eigenvalues = Vec3::Zero();     // of K[3:6, 3:6], ascending, N m/rad
};
CartesianIndices cartesian_indices(const Mat6& K);

}  // namespace kinestat
