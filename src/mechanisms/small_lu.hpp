// Gaussian elimination with partial pivoting for the loaded chains' Newton matrices (fixed_chain.cpp:
// 22-30 rows, factored twice a posture per chain; a third of a loaded map's time in plain column-wise
// loops, whose trip counts of 11 rows on average left the vector units idle). Eigen's PartialPivLU
// takes its blocked path above 16 rows (GEMM updates and packing), slower at this size. Here every
// column is kSmallLUStride doubles apart and its rows past n are zero, so that a column's update runs
// in whole 4-double vectors to a length that depends on n alone (the rows of the first vector that a
// step must not touch are multiplied by an explicit zero); the loops are compiled for AVX2 with FMA
// and for the baseline x86-64, the first picked at load time where the processor has it
// (small_lu.cpp), and the pivot's search keeps four running maxima, not one chain of comparisons.
#pragma once

#include <array>

#include <Eigen/Core>

namespace kinestat::mechanisms::fixed_vjm {

inline constexpr int kSmallLUStride = 32;  // the largest matrix (kMaxCoordinates + 6 = 30 rows), padded

// n x C, column-major, columns kSmallLUStride apart; rows n and beyond zero (as reset() leaves them and
// the solves keep them).
template <int C>
class PaddedColumns {
 public:
  using View =
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, C>, Eigen::Aligned32, Eigen::OuterStride<kSmallLUStride>>;
  // n rows, all zero.
  View reset(int n) {
    n_ = n;
    data_.fill(0.0);
    return view();
  }
  View view() { return View(data_.data(), n_, C); }
  double* data() { return data_.data(); }

 private:
  alignas(32) std::array<double, C * kSmallLUStride> data_;  // not zeroed here: reset() zeroes them
  int n_ = 0;
};

// P A = L U of an n x n matrix A (n <= kSmallLUStride) and solves with it, as often as wanted (a chord
// step reuses the factors of an earlier Newton step).
class SmallLU {
 public:
  using View = Eigen::Map<Eigen::MatrixXd, Eigen::Aligned32, Eigen::OuterStride<kSmallLUStride>>;
  // A, n x n and zero, to fill before factor().
  View reset(int n);
  // Overwrites A by its factors (L below the diagonal, unit diagonal implied; U on and above); false
  // at a zero pivot or one not finite.
  bool factor();
  // B := L^-1 P B (the row exchanges, then L^-1).
  template <int C>
  void forward(PaddedColumns<C>& B) const {
    forward(B.data(), C);
  }
  // The part of B := U^-1 B that pivots from..to-1 of U carry out, from the last: those rows of B
  // solved, the rows above updated by them. Linear in B, so that a combination of columns so treated
  // goes on: backward(B, n - 6, n) gives the last six rows of A^-1 B alone (U is upper triangular),
  // then backward(B, 0, n - 6) the others; backward(B): B := U^-1 B.
  template <int C>
  void backward(PaddedColumns<C>& B, int from = 0, int to = -1) const {
    backward(B.data(), C, from, to < 0 ? n_ : to);
  }
  int rows() const { return n_; }

 private:
  void forward(double* b, int cols) const;
  void backward(double* b, int cols, int from, int to) const;
  alignas(32) std::array<double, kSmallLUStride * kSmallLUStride> a_;  // not zeroed here: reset() zeroes them
  std::array<double, kSmallLUStride> inverse_diagonal_;                // 1 / U(k, k): the solves multiply
  std::array<int, kSmallLUStride> perm_;                               // the row exchanged with k at step k
  int n_ = 0;
};

}  // namespace kinestat::mechanisms::fixed_vjm
