// Warm starts along a path (a map's serpentine rows, PointOrder::kPath): the polynomial through the
// last solved postures (kept in a PathHistory), evaluated at the next point, where those points and
// the next lie on one line at one spacing. Used by the robot kernel's kinematics (robot_kernel.cpp)
// and the loaded mode's equilibria (fixed_chain.cpp).
#pragma once

#include <algorithm>
#include <array>

#include "kinestat/core/types.hpp"

namespace kinestat::mechanisms {

inline constexpr int kMaxExtrapolationOrder = 5;

// Weights of the polynomial through `order` values at equal steps, evaluated one step on, latest
// value first: order 1 the last value, 2 the line, 3 the parabola, 4 the cubic, 5 the quartic; its
// error is of order `order` in the step.
inline constexpr std::array<std::array<double, kMaxExtrapolationOrder>, kMaxExtrapolationOrder> kExtrapolationWeights{
    {{1, 0, 0, 0, 0}, {2, -1, 0, 0, 0}, {3, -3, 1, 0, 0}, {4, -6, 4, -1, 0}, {5, -10, 10, -5, 1}}};

// How many of the last solved points to extrapolate from to `next`: `point(k)` the k-th last (0 the
// latest), `known` of them. All those that continue `next`'s line at its spacing, at most
// kMaxExtrapolationOrder; 1 (the last alone) where the path turns, 0 where none is known.
template <class Point>
int extrapolation_order(const Vec3& next, const Point& point, int known) {
  const auto straight = [](const Vec3& a, const Vec3& b, const Vec3& c) {
    return (a - 2.0 * b + c).norm() <= 1e-9 * (a - b).norm();
  };
  if (known < 2 || !straight(next, point(0), point(1))) return std::min(known, 1);
  int order = 2;
  while (order < std::min(known, kMaxExtrapolationOrder) && straight(point(order - 2), point(order - 1), point(order)))
    ++order;
  return order;
}

// The last N entries solved along a path, latest first, in a ring: push() takes the oldest's place.
template <class T, int N>
class PathHistory {
 public:
  int size() const { return count_; }
  void clear() { count_ = 0; }
  // The k-th last entry (0: the latest), k < size().
  T& operator[](int k) { return ring_[(latest_ + N - k) % N]; }
  const T& operator[](int k) const { return ring_[(latest_ + N - k) % N]; }
  // The new latest entry, for the caller to fill.
  T& push() {
    latest_ = (latest_ + 1) % N;
    count_ = std::min(count_ + 1, N);
    return ring_[latest_];
  }

 private:
  std::array<T, N> ring_{};
  int latest_ = 0, count_ = 0;
};

}  // namespace kinestat::mechanisms
