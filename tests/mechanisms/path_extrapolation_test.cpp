// The warm starts' path helpers (src/mechanisms/path_extrapolation.hpp) against their definitions.
#include "mechanisms/path_extrapolation.hpp"

#include <cmath>

#include <gtest/gtest.h>

namespace kinestat::mechanisms {
namespace {

// The order-k weights are the polynomial of degree k - 1 through k values at equal steps, evaluated
// one step on: exact on such a polynomial (to round-off of values ~10), off on one degree higher.
TEST(PathExtrapolation, WeightsExtrapolateTheirPolynomialsExactly) {
  for (int order = 1; order <= kMaxExtrapolationOrder; ++order) {
    const auto f = [&](double t, int degree) {
      double v = 0.0;
      for (int p = 0; p <= degree; ++p) v += (p + 1.5) * std::pow(t, p);
      return v;
    };
    for (int degree : {order - 1, order}) {
      double predicted = 0.0;  // values at t = 0, -1, -2, ... (latest first), predicted at t = 1
      for (int k = 0; k < order; ++k) predicted += kExtrapolationWeights[order - 1][k] * f(-k, degree);
      if (degree == order - 1)
        EXPECT_NEAR(predicted, f(1.0, degree), 1e-12) << "order " << order;
      else
        EXPECT_GT(std::abs(predicted - f(1.0, degree)), 0.1) << "order " << order;
    }
  }
}

// All the points known that continue the next one's line at its spacing, at most four; one where
// the path turns or the spacing changes; none where none is known.
TEST(PathExtrapolation, OrderFollowsTheStraightRun) {
  const Vec3 step(0.005, 0, 0);
  std::array<Vec3, 6> before;  // before[k]: the k-th last point, on the line through the next one
  for (int k = 0; k < 6; ++k) before[k] = -static_cast<double>(k) * step;
  const Vec3 next = step;
  const auto point = [&](int k) { return before[k]; };
  EXPECT_EQ(extrapolation_order(next, point, 0), 0);
  EXPECT_EQ(extrapolation_order(next, point, 1), 1);
  EXPECT_EQ(extrapolation_order(next, point, 2), 2);
  EXPECT_EQ(extrapolation_order(next, point, 3), 3);
  EXPECT_EQ(extrapolation_order(next, point, 6), kMaxExtrapolationOrder);
  EXPECT_EQ(extrapolation_order(Vec3(0, 0.005, 0), point, 6), 1);  // a turn
  EXPECT_EQ(extrapolation_order(2.0 * step, point, 6), 1);         // another spacing
  before[2] = Vec3(-0.010, 0.001, 0);                              // the run broken two points back
  EXPECT_EQ(extrapolation_order(next, point, 6), 2);
}

// The last N entries, latest first, through more pushes than it holds, and cleared.
TEST(PathExtrapolation, HistoryKeepsTheLastEntriesLatestFirst) {
  PathHistory<int, 4> h;
  EXPECT_EQ(h.size(), 0);
  for (int v = 1; v <= 6; ++v) h.push() = v;
  ASSERT_EQ(h.size(), 4);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(h[k], 6 - k);
  h.clear();
  EXPECT_EQ(h.size(), 0);
  h.push() = 7;
  ASSERT_EQ(h.size(), 1);
  EXPECT_EQ(h[0], 7);
}

}  // namespace
}  // namespace kinestat::mechanisms
