// The beam's geometric stiffness (elements/beam_element.hpp): symmetry, rigid translations, the
// closed-form entries of McGuire-Gallagher-Ziemian eq. (9.18), and the single-element Euler load.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Eigenvalues>

#include "kinestat/core/frame.hpp"
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat {
namespace {

TEST(GeometricStiffness, SymmetricInLocalAndGlobalAxes) {
  const Vec3 p1(0.1, -0.2, 0.3), p2(0.7, 0.4, -0.1);
  Mat3 axes;
  ASSERT_TRUE(element_axes(p1, p2, Vec3(0.3, 0.1, 1.0), axes));
  const Mat12 kl = beam_local_geometric_stiffness(-1234.0, (p2 - p1).norm(), 1e-4);
  const Mat12 T = beam_transformation(axes);
  const Mat12 K = T.transpose() * kl * T;
  EXPECT_EQ((kl - kl.transpose()).norm(), 0.0);  // built entry by entry symmetric
  EXPECT_LT((K - K.transpose()).norm(), 1e-14 * K.norm());
  // Rigid translations stretch nothing: no force.
  for (int k = 0; k < 3; ++k) {
    Vec12 u = Vec12::Zero();
    u.segment<3>(0) = u.segment<3>(6) = Vec3::Unit(k);
    EXPECT_LT((K * u).norm(), 1e-13 * K.norm());
  }
}

TEST(GeometricStiffness, EntriesAndSigns) {
  const double N = -500.0, L = 0.8;
  const Mat12 k = beam_local_geometric_stiffness(N, L, 0.0);
  EXPECT_DOUBLE_EQ(k(1, 1), 6 * N / (5 * L));
  EXPECT_DOUBLE_EQ(k(1, 5), N / 10);
  EXPECT_DOUBLE_EQ(k(5, 5), 2 * N * L / 15);
  EXPECT_DOUBLE_EQ(k(5, 11), -N * L / 30);
  EXPECT_DOUBLE_EQ(k(2, 4), -N / 10);  // x-z plane: opposite coupling, as the elastic matrix
  EXPECT_DOUBLE_EQ(k(4, 10), -N * L / 30);
  EXPECT_DOUBLE_EQ(k(3, 3), 0.0);  // no torsion term asked
  EXPECT_DOUBLE_EQ(beam_local_geometric_stiffness(N, L, 2e-4)(3, 9), -N * 2e-4 / L);
}

TEST(GeometricStiffness, OneElementCantileverBuckling) {
  // One cubic element, clamped at node 1, in one plane: det(K - P G) = 0 on (uy2, rz2) gives the
  // textbook one-element value P = 2.4860 EI/L^2 (exact pi^2/4 = 2.4674: +0.75 %).
  const Material m{"s", 2e11, 8e10};
  const Section sec = rectangle_section(0.02, 0.02);
  const double L = 1.0, EI = m.E * sec.Iz;
  const Mat12 k = beam_local_stiffness(m, sec, L, BeamTheory::kEulerBernoulli);
  const Mat12 g = beam_local_geometric_stiffness(-1.0, L, 0.0);  // unit compression
  Eigen::Matrix2d K, G;
  const int d[2] = {7, 11};
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) K(i, j) = k(d[i], d[j]), G(i, j) = -g(d[i], d[j]);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> ges(K, G);
  const double P = ges.eigenvalues()(0);
  EXPECT_NEAR(P * L * L / EI, 2.4860, 1e-4);
}

}  // namespace
}  // namespace kinestat
