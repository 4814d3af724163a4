// Householder QR of a block of at most 6 x 6 for the per-posture kernels (the VJM's regular
// stiffness, vjm/stiffness.hpp; the robot kinematics' per-leg elimination,
// mechanisms/robot_kinematics.cpp): no posture allocates, and the loops run over the block's own
// rows and columns (Eigen's HouseholderQR, with its dynamic blocks, workspaces and a separate pass to
// form Q, was a third of a generic robot map's time).
#pragma once

#include <cmath>
#include <limits>

#include "kinestat/core/types.hpp"

namespace kinestat {

// A = Q R for the top-left rows x cols block of A (cols <= rows <= 6; the rest of A zero): R in
// A's upper cols x cols triangle (zeros below), Q (the top-left rows x rows block of `Q`, the rest
// identity) orthogonal; Q's columns cols..rows-1 span the complement of A's range. Returns the
// reflections applied: det Q = (-1)^count. The reflections are Eigen's (makeHouseholder): for a
// column x = (c, t), beta = -sign(c) |x|, v = (1, t / (c - beta)), tau = (beta - c) / beta, and none
// where t is zero (a column already along its axis). A zero column gives R(k, k) = 0: the caller's
// rank test fails.
inline int householder_qr(Mat6& A, int rows, int cols, Mat6& Q) {
  double v[6][6];  // v[k][i], i > k: the essential part of reflection k (v[k][k] = 1)
  double tau[6];
  int count = 0;
  for (int k = 0; k < cols; ++k) {
    double tail = 0.0;
    for (int i = k + 1; i < rows; ++i) tail += A(i, k) * A(i, k);
    const double c = A(k, k);
    if (tail <= std::numeric_limits<double>::min()) {
      tau[k] = 0.0;
      for (int i = k + 1; i < rows; ++i) A(i, k) = 0.0;
      continue;
    }
    double beta = std::sqrt(c * c + tail);
    if (c >= 0.0) beta = -beta;
    const double scale = 1.0 / (c - beta);
    for (int i = k + 1; i < rows; ++i) {
      v[k][i] = A(i, k) * scale;
      A(i, k) = 0.0;
    }
    tau[k] = (beta - c) / beta;
    A(k, k) = beta;
    ++count;
    for (int j = k + 1; j < cols; ++j) {  // H_k = I - tau v v^T on the columns to come
      double s = A(k, j);
      for (int i = k + 1; i < rows; ++i) s += v[k][i] * A(i, j);
      s *= tau[k];
      A(k, j) -= s;
      for (int i = k + 1; i < rows; ++i) A(i, j) -= s * v[k][i];
    }
  }
  // Q = H_0 H_1 ... H_(cols-1): the identity, reflected from the last one on; H_k leaves the rows and
  // columns before k alone.
  Q.setIdentity();
  for (int k = cols - 1; k >= 0; --k) {
    if (tau[k] == 0.0) continue;
    for (int j = k; j < rows; ++j) {
      double s = Q(k, j);
      for (int i = k + 1; i < rows; ++i) s += v[k][i] * Q(i, j);
      s *= tau[k];
      Q(k, j) -= s;
      for (int i = k + 1; i < rows; ++i) Q(i, j) -= s * v[k][i];
    }
  }
  return count;
}

}  // namespace kinestat
