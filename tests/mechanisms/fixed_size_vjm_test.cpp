// The sweep kernels' fixed-size pieces (src/mechanisms/fixed_size_vjm.hpp) against their definitions.
#include "mechanisms/fixed_size_vjm.hpp"

#include <gtest/gtest.h>

namespace kinestat::mechanisms::fixed_vjm {
namespace {

// K = Q diag(1, 2, 3, 4, 5, r) P^T with Q, P orthogonal: singular values 5 .. r, the ratio
// sigma_min / sigma_max = r / 5 against vjm's tolerance 1e-10 (the line r = 5e-10). With r = 2e-9 and
// above the norms decide (1 / |C|_F ~ r > 1e-10 |K|_F = 7.4e-10), and C is the inverse to round-off
// (cond K eps); with r = 6e-10 (a ratio of 1.2e-10) and 3e-10 (6e-11) they cannot, and the SVD
// decides each way; a rank-deficient K is refused.
TEST(FixedSizeVjm, RegularInverseIsTheRankTestOfTheSvd) {
  const Mat6 Q = Eigen::HouseholderQR<Mat6>(Mat6::Random()).householderQ();
  const Mat6 P = Eigen::HouseholderQR<Mat6>(Mat6::Random()).householderQ();
  const auto make = [&](double r) {
    Vec6 s;
    s << 1, 2, 3, 4, 5, r;
    return Mat6(Q * s.asDiagonal() * P.transpose());
  };
  Mat6 C;
  for (double r : {1.0, 1e-3, 1e-8, 2e-9}) {
    const Mat6 K = make(r);
    ASSERT_TRUE(regular_inverse(K, 1e-10, C)) << r;
    EXPECT_LT((C * K - Mat6::Identity()).norm(), 1e-14 / r) << r;
  }
  EXPECT_TRUE(regular_inverse(make(6e-10), 1e-10, C));
  EXPECT_FALSE(regular_inverse(make(3e-10), 1e-10, C));
  EXPECT_FALSE(regular_inverse(make(0.0), 1e-10, C));
}

}  // namespace
}  // namespace kinestat::mechanisms::fixed_vjm
