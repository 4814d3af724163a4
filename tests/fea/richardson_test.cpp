#include <gtest/gtest.h>

#include <cmath>

#include "kinestat/fea/mesh_convergence.hpp"

namespace kinestat::fea {
namespace {

// f = 1 + 2 h^p is exactly the Richardson model: the estimate must recover p and the limit 1,
// also for unequal refinement ratios.
TEST(Richardson, RecoversOrderAndLimitOfAPowerLaw) {
  for (double p : {1.0, 2.0, 3.5}) {
    const std::vector<double> h = {0.3, 0.2, 0.08};
    std::vector<double> f;
    for (double x : h) f.push_back(1.0 + 2.0 * std::pow(x, p));
    auto r = richardson_estimate(h, f);
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_NEAR(r->order, p, 1e-8);
    EXPECT_NEAR(r->extrapolated, 1.0, 1e-10);
    EXPECT_NEAR(r->finest_error, 2.0 * std::pow(0.08, p), 1e-10);
  }
}

TEST(Richardson, OscillatingSequenceIsNotConverged) {
  auto r = richardson_estimate({0.4, 0.2, 0.1}, {1.1, 0.95, 1.02});
  EXPECT_EQ(r.status().code(), StatusCode::kNotConverged);
  EXPECT_EQ(richardson_estimate({0.1, 0.2, 0.05}, {1, 2, 3}).status().code(), StatusCode::kInvalidInput);
}

}  // namespace
}  // namespace kinestat::fea
