#include "mechanisms/small_lu.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

// The loops twice: for AVX2 with FMA (x86-64-v3, the processors since 2013) and the baseline, picked
// at load time (GCC's function multiversioning); elsewhere once.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define KINESTAT_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define KINESTAT_VECTOR_CLONES
#endif

namespace kinestat::mechanisms::fixed_vjm {

namespace {

constexpr int S = kSmallLUStride;

// Rows beyond n are zero: a column's vector loop may run on to the padded length.
int padded(int n) { return (n + 3) & ~3; }

// y[i] -= x[i] s for i in [0, end): in 4-double vectors, then singly.
inline void axpy(double* __restrict y, const double* __restrict x, double s, int end) {
  int i = 0;
  for (; i + 4 <= end; i += 4)
    for (int t = 0; t < 4; ++t) y[i + t] -= x[i + t] * s;
  for (; i < end; ++i) y[i] -= x[i] * s;
}

// Column x of L below row k (k + 1 < n), rows k + 1 .. P - 1, in whole vectors from the one holding
// row k + 1: that first vector a copy with zeros on and above row k, the others read in place. An
// update y -= x s over those vectors leaves the rows up to k as they were, in loops of one length for
// all the columns of a step.
struct BelowDiagonal {
  const double* x;
  int begin;
  alignas(32) std::array<double, 4> head;
  BelowDiagonal(const double* x, int k) : x(x), begin((k + 1) & ~3) {
    for (int t = 0; t < 4; ++t) head[t] = begin + t > k ? x[begin + t] : 0.0;
  }
  void update(double* __restrict y, double s, int P) const {
    for (int t = 0; t < 4; ++t) y[begin + t] -= head[t] * s;
    for (int i = begin + 4; i < P; i += 4)
      for (int t = 0; t < 4; ++t) y[i + t] -= x[i + t] * s;
  }
};

}  // namespace

SmallLU::View SmallLU::reset(int n) {
  n_ = n;
  for (int j = 0; j < n; ++j) std::fill_n(a_.data() + j * S, padded(n), 0.0);
  return View(a_.data(), n, n);
}

KINESTAT_VECTOR_CLONES bool SmallLU::factor() {
  const int n = n_, P = padded(n);
  double* a = a_.data();
  for (int k = 0; k < n; ++k) {
    double* ck = a + k * S;
    // The pivot: the first largest |A(i, k)|, in two passes: its value in 4 running maxima (one chain
    // of comparisons from row to row would take longer than the column's update), then its row.
    double largest = 0.0;
    int i = k;
    for (; i < P && (i & 3) != 0; ++i) largest = std::max(largest, std::abs(ck[i]));
    std::array<double, 4> most{};
    for (; i < P; i += 4)
      for (int t = 0; t < 4; ++t) most[t] = std::max(most[t], std::abs(ck[i + t]));
    largest = std::max({largest, most[0], most[1], most[2], most[3]});
    if (!(largest != 0.0) || !std::isfinite(largest)) return false;
    int p = k;
    while (std::abs(ck[p]) != largest) ++p;
    perm_[k] = p;
    if (p != k)
      for (int j = 0; j < n; ++j) std::swap(a[j * S + p], a[j * S + k]);
    const double r = inverse_diagonal_[k] = 1.0 / ck[k];
    if (k + 1 == n) break;
    for (int i = k + 1; i < n; ++i) ck[i] *= r;  // the multipliers
    const BelowDiagonal l(ck, k);
    for (int j = k + 1; j < n; ++j)
      if (const double s = a[j * S + k]; s != 0.0) l.update(a + j * S, s, P);
  }
  return true;
}

KINESTAT_VECTOR_CLONES void SmallLU::forward(double* b, int cols) const {
  const int n = n_, P = padded(n);
  const double* a = a_.data();
  for (int k = 0; k < n; ++k)
    if (perm_[k] != k)
      for (int c = 0; c < cols; ++c) std::swap(b[c * S + perm_[k]], b[c * S + k]);
  for (int k = 0; k + 1 < n; ++k) {
    const BelowDiagonal l(a + k * S, k);
    for (int c = 0; c < cols; ++c)
      if (const double s = b[c * S + k]; s != 0.0) l.update(b + c * S, s, P);
  }
}

KINESTAT_VECTOR_CLONES void SmallLU::backward(double* b, int cols, int from, int to) const {
  for (int c = 0; c < cols; ++c)
    for (int k = to - 1; k >= from; --k)
      if (const double x = b[c * S + k] *= inverse_diagonal_[k]; x != 0.0) axpy(b + c * S, a_.data() + k * S, x, k);
}

}  // namespace kinestat::mechanisms::fixed_vjm
