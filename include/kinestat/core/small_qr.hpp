// Householder QR of a block of at most 6 x 6, on the stack, for the per-posture kernels (the VJM's
// regular stiffness, vjm/stiffness.hpp; the robot kinematics' per-leg elimination,
// mechanisms/robot_kinematics.cpp): Eigen's decompositions of dynamic size allocate, and at these
// sizes their blocked paths cost more than the arithmetic.
#pragma once

#include "kinestat/core/types.hpp"

namespace kinestat {

// A = Q R for the top-left rows x cols block of A (cols <= rows <= 6; the rest of A zero): R in
// A's upper cols x cols triangle (zeros below, to round-off), Q (the top-left rows x rows block
// of `Q`, the rest identity) orthogonal; Q's columns cols..rows-1 span the complement of A's
// range. Returns the reflections applied: det Q = (-1)^count. A zero column is left as it is
// (R(k, k) = 0: the caller's rank test fails).
inline int householder_qr(Mat6& A, int rows, int cols, Mat6& Q) {
  Q.setIdentity();
  int count = 0;
  for (int k = 0; k < cols; ++k) {
    Vec6 v = Vec6::Zero();
    v.segment(k, rows - k) = A.col(k).segment(k, rows - k);
    const double norm = v.norm();
    if (norm == 0.0) continue;
    v(k) += v(k) > 0 ? norm : -norm;  // no cancellation: R(k, k) = -sign(A(k, k)) norm
    const double vv = v.squaredNorm();
    for (int j = k; j < cols; ++j) A.col(j) -= (2.0 * v.dot(A.col(j)) / vv) * v;
    Q -= (2.0 / vv) * (Q * v) * v.transpose();
    ++count;
  }
  return count;
}

}  // namespace kinestat
