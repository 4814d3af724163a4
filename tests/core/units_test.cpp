// The unit constants (core/units.hpp) against their definitions, written here independently: every
// reader, option and report converts through them.
#include "kinestat/core/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace kinestat::units {
namespace {

TEST(Units, EachConstantIsTheSiValueOfOneUnit) {
  EXPECT_EQ(kMm, 0.001);
  EXPECT_EQ(kCm, 0.01);
  EXPECT_EQ(kInch, 0.0254);  // international inch (1959), exact
  EXPECT_EQ(kFoot, 0.3048);  // 12 in, exact
  EXPECT_DOUBLE_EQ(kFoot, 12 * kInch);
  EXPECT_EQ(kNMm, 0.001);
  EXPECT_EQ(kKN, 1000.0);
  EXPECT_EQ(kMPa, 1e6);
  EXPECT_DOUBLE_EQ(kMPa, 1.0 / (kMm * kMm));     // N/mm^2
  EXPECT_DOUBLE_EQ(kLbf, 0.45359237 * 9.80665);  // avoirdupois pound x standard gravity, exact
  EXPECT_DOUBLE_EQ(kKip, 1000.0 * kLbf);
  EXPECT_DOUBLE_EQ(180.0 * kDeg, std::numbers::pi);
  EXPECT_DOUBLE_EQ(std::sin(30.0 * kDeg), 0.5);
}

}  // namespace
}  // namespace kinestat::units
