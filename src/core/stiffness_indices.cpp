#include "kinestat/core/stiffness_indices.hpp"

#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace kinestat {

namespace {

// Eq. (7)-(13) of K, for both sizes; the eigenvectors into `vectors` unless it is null.
template <int N>
void compute_indices(const Eigen::Matrix<double, N, N>& K, MatrixIndices<N>& s, Eigen::Matrix<double, N, N>* vectors) {
  using Matrix = Eigen::Matrix<double, N, N>;
  const double fro = K.norm();
  s.norm_frobenius = fro;
  s.symmetry_error = fro > 0 ? (K - K.transpose()).norm() / fro : 0.0;
  s.trace = K.trace();
  s.norm_1 = K.cwiseAbs().colwise().sum().maxCoeff();
  s.norm_inf = K.cwiseAbs().rowwise().sum().maxCoeff();
  s.max_abs_entry = K.cwiseAbs().maxCoeff();

  const Matrix Ks = 0.5 * (K + K.transpose());
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(Ks, vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  s.eigenvalues = eig.eigenvalues();
  if (vectors) *vectors = eig.eigenvectors();
  const auto a = s.eigenvalues.cwiseAbs();
  s.norm_2 = a.maxCoeff();
  const double amin = a.minCoeff();
  s.condition_number = amin > 0 ? s.norm_2 / amin : std::numeric_limits<double>::infinity();

  // Determinant through an LU factorization with partial pivoting, accumulated in logs.
  const Eigen::PartialPivLU<Matrix> lu(K);
  int sign = static_cast<int>(lu.permutationP().determinant());
  double log10_det = 0.0;
  for (Eigen::Index i = 0; i < K.rows(); ++i) {
    const double d = lu.matrixLU()(i, i);
    if (d == 0.0) {
      sign = 0;
      break;
    }
    if (d < 0) sign = -sign;
    log10_det += std::log10(std::abs(d));
  }
  s.det_sign = sign;
  s.log10_abs_det = sign == 0 ? -std::numeric_limits<double>::infinity() : log10_det;
  if (sign == 0) {
    s.determinant = 0.0;
  } else if (log10_det > 307.0) {
    s.determinant = sign * std::numeric_limits<double>::infinity();
  } else {
    s.determinant = sign * std::pow(10.0, log10_det);
  }
}

}  // namespace

StiffnessIndices stiffness_indices(const MatX& K) {
  StiffnessIndices s;
  s.size = static_cast<int>(K.rows());
  if (K.rows() == 0 || K.rows() != K.cols()) return s;
  compute_indices<Eigen::Dynamic>(K, s, &s.eigenvectors);
  return s;
}

CartesianIndices cartesian_indices(const Mat6& K) {
  CartesianIndices s;
  compute_indices<6>(K, s, nullptr);  // the sweep path needs the spectrum, not the directions
  const Mat6 Ks = 0.5 * (K + K.transpose());
  s.translational_eigenvalues =
      Eigen::SelfAdjointEigenSolver<Mat3>(Ks.topLeftCorner<3, 3>(), Eigen::EigenvaluesOnly).eigenvalues();
  s.rotational_eigenvalues =
      Eigen::SelfAdjointEigenSolver<Mat3>(Ks.bottomRightCorner<3, 3>(), Eigen::EigenvaluesOnly).eigenvalues();
  return s;
}

std::string indices_report(const StiffnessIndices& ix) {
  std::string out;
  out += fmt::format("    size {}x{}, symmetry error {:.1e}\n", ix.size, ix.size, ix.symmetry_error);
  out += fmt::format(
      "    determinant       {} (sign {}, log10|det| = {:.4f})\n",
      std::isfinite(ix.determinant) ? fmt::format("{:.4e}", ix.determinant) : std::string("overflows double"),
      ix.det_sign, ix.log10_abs_det);
  out += fmt::format("    trace             {:.4e}\n", ix.trace);
  out += fmt::format("    1-norm            {:.4e}\n", ix.norm_1);
  out += fmt::format("    2-norm            {:.4e}\n", ix.norm_2);
  out += fmt::format("    Frobenius norm    {:.4e}\n", ix.norm_frobenius);
  out += fmt::format("    inf-norm (rows)   {:.4e}\n", ix.norm_inf);
  out += fmt::format("    max |k_ij|        {:.4e}\n", ix.max_abs_entry);
  out += fmt::format("    condition number  {:.4e}\n", ix.condition_number);
  return out;
}

}  // namespace kinestat
