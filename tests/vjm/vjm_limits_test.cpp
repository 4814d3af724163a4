// Size and range checks of the VJM computations (docs/reliability.md): a chain whose dense matrices
// would not fit is refused before they are allocated, with the count and the option that raises the
// limit; prescribed displacements and wrenches must be finite and in range.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "vjm_test_chains.hpp"

namespace kinestat::vjm {
namespace {

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

// n identical 6-dof springs in series along x: 6 n virtual coordinates, compliance n / k in every
// direction at the tool when the springs sit at the tool point (no lever arm).
Chain spring_stack(int n, double k) {
  Chain c("stack");
  for (int i = 0; i < n; ++i) c.add_spring(k * Mat6::Identity(), "spring " + std::to_string(i + 1));
  return c;
}

TEST(VjmLimits, LongChainIsRefusedBeforeItsMatricesExist) {
  // 6000 coordinates: 36e6 doubles per dense matrix, above the default limit; refused at once.
  const Chain c = spring_stack(1000, 1e6);
  StatusOr<CartesianStiffness> K = unloaded_stiffness(c);
  ASSERT_FALSE(K.ok());
  EXPECT_EQ(K.status().code(), StatusCode::kInvalidInput);
  expect_contains(K.status().message(), "chain 'stack': about 6e+03 coordinates");
  expect_contains(K.status().message(), "above the limit of 5e+03");
  expect_contains(K.status().message(), "--max-coordinates");
  EXPECT_FALSE(chain_equilibrium(c, Vec6::Zero()).ok());
}

TEST(VjmLimits, TheLimitIsAnOption) {
  const Chain c = spring_stack(10, 1e6);  // 60 coordinates
  StiffnessOptions low;
  low.max_chain_coordinates = 59;
  EXPECT_EQ(unloaded_stiffness(c, low).status().code(), StatusCode::kInvalidInput);
  low.max_chain_coordinates = 60;
  StatusOr<CartesianStiffness> K = unloaded_stiffness(c, low);
  ASSERT_TRUE(K.ok()) << K.status().message();
  EXPECT_NEAR(K->stiffness(0, 0), 1e5, 1e-6);  // ten springs k in series: k / 10
  EXPECT_NEAR(K->stiffness(5, 5), 1e5, 1e-6);
}

TEST(VjmLimits, LoadedStiffnessOfAChainWithoutPassiveJoints) {
  // No passive joint: the blocks coupling q are empty (the LU solve on them was undefined behaviour).
  const Chain c = spring_stack(2, 1e4);
  StatusOr<ChainState> s = chain_equilibrium(c, (Vec6() << 1e-6, 0, 0, 0, 0, 0).finished());
  ASSERT_TRUE(s.ok()) << s.status().message();
  StatusOr<CartesianStiffness> K = loaded_stiffness(c, *s);
  ASSERT_TRUE(K.ok()) << K.status().message();
  EXPECT_NEAR(K->stiffness(0, 0), 5e3, 1e-6 * 5e3);  // two springs of 1e4 in series
}

TEST(VjmLimits, PrescribedDisplacementAndWrenchMustBeFiniteAndInRange) {
  const std::vector<Chain> chains = {test_chains::pendulum(200.0, 1e5, 0.5)};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  StatusOr<PlatformState> a = platform_equilibrium(chains, (Vec6() << nan, 0, 0, 0, 0, 0).finished());
  ASSERT_EQ(a.status().code(), StatusCode::kInvalidInput);
  expect_contains(a.status().message(), "the prescribed displacement dx = nan m is not a finite number");
  StatusOr<PlatformState> b = platform_equilibrium_under_wrench(chains, (Vec6() << 0, 0, 0, 0, 0, 1e300).finished());
  ASSERT_EQ(b.status().code(), StatusCode::kInvalidInput);
  expect_contains(b.status().message(), "the prescribed wrench Mz = 1e+300 N m is too large for a moment");
}

}  // namespace
}  // namespace kinestat::vjm
