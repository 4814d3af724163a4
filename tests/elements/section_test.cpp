// Section scaling: every dimension times f gives areas times f^2 and second moments times f^4, so a
// scaled tube is the tube of scaled diameter and wall (the identification of docs/vjm.md relies on it).
#include <gtest/gtest.h>

#include "kinestat/elements/section.hpp"

namespace kinestat {
namespace {

void expect_same(const Section& a, const Section& b) {
  EXPECT_NEAR(a.A, b.A, 1e-12 * b.A);
  EXPECT_NEAR(a.Iy, b.Iy, 1e-12 * b.Iy);
  EXPECT_NEAR(a.Iz, b.Iz, 1e-12 * b.Iz);
  EXPECT_NEAR(a.J, b.J, 1e-12 * b.J);
  EXPECT_NEAR(a.Asy, b.Asy, 1e-12 * b.Asy);
  EXPECT_NEAR(a.Asz, b.Asz, 1e-12 * b.Asz);
}

TEST(ScaledSection, IsTheSectionOfScaledDimensions) {
  expect_same(scaled_section(tube_section(0.020, 0.002), 0.743663), tube_section(0.020 * 0.743663, 0.002 * 0.743663));
  expect_same(scaled_section(hollow_rectangle_section(0.06, 0.04, 0.005), 1.7),
              hollow_rectangle_section(0.06 * 1.7, 0.04 * 1.7, 0.005 * 1.7));
  // The exact Saint-Venant J of a rectangle scales as f^4 too (its series depends on b/h only).
  expect_same(scaled_section(rectangle_section(0.03, 0.01), 0.5), rectangle_section(0.015, 0.005));
}

}  // namespace
}  // namespace kinestat
