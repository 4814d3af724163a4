// The beam's geometric stiffness (elements/beam_element.hpp): symmetry, rigid translations, the
// closed-form entries of McGuire-Gallagher-Ziemian eq. (9.18), the single-element Euler load, and the
// shear-deformable (Timoshenko) terms of Frame3DD's variant.
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

// The shear-deformable terms (GeometricStiffnessTerms::shear, Frame3DD's geometric_K) are the
// consistent K_G N * integral(w_i' w_j' dx) of the Timoshenko beam's cubic shape functions for the
// transverse displacement (Friedman & Kosmatka, "An improved two-node Timoshenko beam finite
// element", Computers & Structures 47 (1993) 473-481, eq. (21)): integrated here by 4-point Gauss
// (exact for their degree-4 products), against the matrix for Phi = 0.3 and 0.05 in the two planes.
TEST(GeometricStiffness, ShearTermsAreTheConsistentMatrixOfTimoshenkoShapeFunctions) {
  const double N = -700.0, L = 1.3;
  GeometricStiffnessTerms terms;
  terms.shear = {0.3, 0.05};
  terms.axial = false;
  const Mat12 k = beam_local_geometric_stiffness(N, L, terms);
  // d/dx of (w1, th1, w2, th2)'s shape functions at xi = x / L.
  auto slopes = [L](double phi, double xi) {
    const double c = 1.0 / (1.0 + phi);
    return Eigen::Vector4d(c * (6 * xi * xi - 6 * xi - phi) / L, c * (3 * xi * xi - (4 + phi) * xi + 1 + phi / 2),
                           c * (-6 * xi * xi + 6 * xi + phi) / L, c * (3 * xi * xi - (2 - phi) * xi - phi / 2));
  };
  const double g[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
  const double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
  for (int plane = 0; plane < 2; ++plane) {
    const double phi = plane == 0 ? terms.shear.phi_y : terms.shear.phi_z;
    Eigen::Matrix4d ref = Eigen::Matrix4d::Zero();
    for (int q = 0; q < 4; ++q) {
      const Eigen::Vector4d d = slopes(phi, 0.5 * (g[q] + 1));
      ref += N * 0.5 * L * w[q] * d * d.transpose();
    }
    // x-y plane (uy, rz) as the functions are written; x-z plane (uz, ry) with ry = -w'.
    const int dy[4] = {1, 5, 7, 11}, dz[4] = {2, 4, 8, 10};
    const double sz[4] = {1, -1, 1, -1};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const double mine = plane == 0 ? k(dy[i], dy[j]) : sz[i] * sz[j] * k(dz[i], dz[j]);
        EXPECT_NEAR(mine, ref(i, j), 1e-12 * std::abs(N) * L) << "plane " << plane << " " << i << j;
      }
  }
  EXPECT_EQ(k(0, 0), 0.0);  // no axial term asked
  EXPECT_EQ(k(0, 6), 0.0);
  // Phi = 0 and the axial term: the Euler-Bernoulli matrix.
  EXPECT_TRUE(beam_local_geometric_stiffness(N, L, GeometricStiffnessTerms{2e-4, true, {}}) ==
              beam_local_geometric_stiffness(N, L, 2e-4));
}

}  // namespace
}  // namespace kinestat
