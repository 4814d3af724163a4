// The range and size checks every reader and option goes through (core/input_checks.hpp): a value is
// judged after its conversion to SI and reported in the unit it was written in.
#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace kinestat {
namespace {

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

const UnitOfInput kMm{units::kMm, "mm"};

TEST(InputChecks, LengthRangeIsJudgedInSiAndReportedInTheWrittenUnit) {
  EXPECT_TRUE(check_quantity(1e9, Quantity::kLength, "x", kMm).ok());  // 1e6 m: the bound itself
  const Status s = check_quantity(1e300, Quantity::kLength, "node 'B': 'xyz'", kMm);
  ASSERT_EQ(s.code(), StatusCode::kInvalidInput);
  expect_contains(s.message(), "node 'B': 'xyz' = 1e+300 mm is too large for a length (|value| <= 1e+09 mm)");
}

TEST(InputChecks, OverflowAfterConversionIsCaughtBeforeTheProduct) {
  // 1e305 MPa is finite as written but 1e311 Pa overflows: refused by comparing in MPa.
  const Status s = check_quantity(1e305, Quantity::kModulus, "'E'", {1e6, "MPa"}, Sign::kPositive);
  ASSERT_FALSE(s.ok());
  expect_contains(s.message(), "'E' = 1e+305 MPa is too large for a modulus (|value| <= 1e+09 MPa)");
}

TEST(InputChecks, NotFiniteSignAndSmallness) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  expect_contains(check_quantity(nan, Quantity::kLength, "--size", kMm).message(), "--size = nan mm is not a finite");
  expect_contains(check_quantity(-5, Quantity::kLength, "--size", kMm, Sign::kPositive).message(),
                  "--size = -5 mm must be positive");
  expect_contains(check_quantity(-1, Quantity::kTranslationalStiffness, "k", {}, Sign::kNonNegative).message(),
                  "k = -1 N/m must not be negative");
  EXPECT_TRUE(check_quantity(0, Quantity::kTranslationalStiffness, "k", {}, Sign::kNonNegative).ok());
  // Positive but below a nanometre: underflows in section properties (d^4).
  expect_contains(check_quantity(1e-10, Quantity::kLength, "d", kMm, Sign::kPositive).message(),
                  "too small for a length (at least 1e-06 mm)");
}

TEST(InputChecks, SizeLimitNamesTheEstimateTheLimitAndTheAdvice) {
  EXPECT_TRUE(check_size(2e6, 2e6, "grid", "points", "raise --max-points").ok());
  const Status s = check_size(1e15, 2e6, "--vtk-grid 100000", "points (N^3)", "raise it with --max-points");
  ASSERT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_EQ(s.message(),
            "--vtk-grid 100000: about 1e+15 points (N^3), above the limit of 2e+06; raise it with "
            "--max-points");
  EXPECT_FALSE(check_size(std::nan(""), 1.0, "x", "y", "z").ok());  // an estimate that is not a number
}

TEST(InputChecks, DirectionAndSource) {
  EXPECT_TRUE(check_direction(Vec3(1e300, 1e300, 0), "axis").ok());  // huge but a direction
  EXPECT_FALSE(check_direction(Vec3::Zero(), "axis").ok());
  EXPECT_FALSE(check_direction(Vec3(0, std::numeric_limits<double>::infinity(), 0), "axis").ok());
  EXPECT_EQ(at_source("m.yaml:3", "joint 'j'"), "m.yaml:3: joint 'j'");
  EXPECT_EQ(at_source("", "joint 'j'"), "joint 'j'");
}

}  // namespace
}  // namespace kinestat
