// Householder QR of a block of at most 6 x 6 for the per-posture kernels (the VJM's regular
// stiffness, vjm/stiffness.hpp; the robot kinematics' per-leg elimination,
// mechanisms/robot_kinematics.cpp): Eigen's HouseholderQR on a matrix of fixed capacity 6 x 6, so
// that no posture allocates.
#pragma once

#include <Eigen/QR>

#include "kinestat/core/types.hpp"

namespace kinestat {

// A = Q R for the top-left rows x cols block of A (cols <= rows <= 6; the rest of A zero): R in
// A's upper cols x cols triangle (zeros below), Q (the top-left rows x rows block of `Q`, the rest
// identity) orthogonal; Q's columns cols..rows-1 span the complement of A's range. Returns the
// reflections applied: det Q = (-1)^count (Eigen skips the reflection of a column already along its
// axis). A zero column gives R(k, k) = 0: the caller's rank test fails.
inline int householder_qr(Mat6& A, int rows, int cols, Mat6& Q) {
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  const Eigen::HouseholderQR<Small> qr(Small(A.topLeftCorner(rows, cols)));
  A.setZero();
  A.topLeftCorner(rows, cols) = qr.matrixQR().triangularView<Eigen::Upper>();
  Q.setIdentity();
  Q.topLeftCorner(rows, rows) = qr.householderQ();
  int count = 0;
  for (Eigen::Index k = 0; k < qr.hCoeffs().size(); ++k) count += qr.hCoeffs()(k) != 0.0;
  return count;
}

}  // namespace kinestat
