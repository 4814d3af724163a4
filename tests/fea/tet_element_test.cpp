// Element-level checks of the 4- and 10-node tetrahedra against elasticity theory.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "fea/elasticity_assembly.hpp"
#include "kinestat/core/frame.hpp"
#include "kinestat/fea/tet_element.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {
namespace {

const Material kSteel = Material::from_E_nu("steel", 210e9, 0.3);

// A skewed reference tetrahedron (vertices) and its quadratic version.
std::vector<Vec3> element_nodes(int n) {
  std::vector<Vec3> x = {{0.01, 0.0, 0.0}, {0.05, 0.01, 0.0}, {0.02, 0.04, 0.005}, {0.015, 0.01, 0.03}};
  if (n == 10)
    for (const auto& e : kTet10Edges) x.push_back(0.5 * (x[e[0]] + x[e[1]]));
  return x;
}

double tet_volume(const std::vector<Vec3>& x) { return (x[1] - x[0]).dot((x[2] - x[0]).cross(x[3] - x[0])) / 6.0; }

class TetElement : public ::testing::TestWithParam<int> {};

TEST_P(TetElement, SymmetricAndFreeOfForceUnderRigidMotion) {
  const int n = GetParam();
  const auto x = element_nodes(n);
  const MatX K = tet_stiffness(x.data(), n, elasticity_matrix(kSteel));
  ASSERT_EQ(K.rows(), 3 * n);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  // Six rigid modes (translations, small rotations about an arbitrary point): zero nodal forces.
  for (int m = 0; m < 6; ++m) {
    Vec6 q = Vec6::Zero();
    q(m) = 1.0;
    VecX u(3 * n);
    for (int a = 0; a < n; ++a) u.segment<3>(3 * a) = rigid_transfer(x[a] - Vec3(0.3, -0.2, 0.1)).topRows<3>() * q;
    EXPECT_LT((K * u).norm(), 1e-9 * K.norm() * u.norm()) << "mode " << m;
  }
  // Exactly six zero eigenvalues, the others positive.
  Eigen::SelfAdjointEigenSolver<MatX> eig(K);
  EXPECT_LT(std::abs(eig.eigenvalues()(5)), 1e-9 * eig.eigenvalues().maxCoeff());
  EXPECT_GT(eig.eigenvalues()(6), 1e-6 * eig.eigenvalues().maxCoeff());
}

TEST_P(TetElement, StrainEnergyOfUniformStrainMatchesTheory) {
  // u = E x (E symmetric) is a uniform strain: U = 1/2 u^T K u must equal 1/2 eps^T D eps V.
  const int n = GetParam();
  const auto x = element_nodes(n);
  const Mat6 D = elasticity_matrix(kSteel);
  const MatX K = tet_stiffness(x.data(), n, D);
  Mat3 strain;
  strain << 1e-3, 2e-4, -3e-4, 2e-4, -5e-4, 1e-4, -3e-4, 1e-4, 7e-4;
  VecX u(3 * n);
  for (int a = 0; a < n; ++a) u.segment<3>(3 * a) = strain * x[a];
  Vec6 eps;
  eps << strain(0, 0), strain(1, 1), strain(2, 2), 2 * strain(1, 2), 2 * strain(0, 2), 2 * strain(0, 1);
  const double expected = 0.5 * eps.dot(D * eps) * tet_volume(x);
  EXPECT_NEAR(0.5 * u.dot(K * u), expected, 1e-10 * expected);
}

TEST_P(TetElement, MassCarriesTheElementsMassAndRotaryInertia) {
  // Rigid motions are in both elements' displacement spaces, so the consistent mass must give their
  // kinetic energies exactly: a translation the mass rho V, a rotation about any axis the rigid
  // body's rotary inertia, from the second moments of a tetrahedron (vertices y_i about the point p):
  // S = integral of y y^T dV = V/20 (sum y_i y_i^T + (sum y_i)(sum y_i)^T), I = rho (tr S 1 - S).
  const int n = GetParam();
  const auto x = element_nodes(n);
  const double rho = 7850.0, V = tet_volume(x);
  const MatX M = tet_mass(x.data(), n, rho);
  ASSERT_EQ(M.rows(), 3 * n);
  EXPECT_LT((M - M.transpose()).norm(), 1e-15 * M.norm());
  for (int d = 0; d < 3; ++d) {
    double sum = 0.0;  // every entry of direction d's block: r_d^T M r_d
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) sum += M(3 * a + d, 3 * b + d);
    EXPECT_NEAR(sum, rho * V, 1e-14 * rho * V) << "direction " << d;  // measured: at most 8.6e-16 relative
  }
  const Vec3 p(0.3, -0.2, 0.1);
  Mat3 S = Mat3::Zero();
  Vec3 sum_y = Vec3::Zero();
  for (int a = 0; a < 4; ++a) {
    S += (x[a] - p) * (x[a] - p).transpose();
    sum_y += x[a] - p;
  }
  S = V / 20.0 * (S + sum_y * sum_y.transpose());
  const Mat3 I = rho * (S.trace() * Mat3::Identity() - S);
  for (const Vec3& omega : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(0.3, -0.8, 0.5)}) {
    VecX v(3 * n);
    for (int a = 0; a < n; ++a) v.segment<3>(3 * a) = omega.cross(x[a] - p);
    const double expected = 0.5 * omega.dot(I * omega);
    EXPECT_NEAR(0.5 * v.dot(M * v), expected, 1e-13 * expected) << omega.transpose();  // measured: at most 1.6e-15
  }
  // Positive definite: every node carries mass.
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatX>(M).eigenvalues().minCoeff(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(LinearAndQuadratic, TetElement, ::testing::Values(4, 10));

// The closed forms of the straight-sided elements' consistent masses (Zienkiewicz & Taylor; from
// the integrals of products of volume coordinates): 4 nodes rho V/20 (2 on the diagonal, 1 off it);
// 10 nodes rho V/420 times 6 (vertex diagonal), 1 (two vertices), -4 (a vertex and a mid-edge node
// of its edges), -6 (of the opposite edges), 32 (mid-edge diagonal), 16 (two edges sharing a vertex),
// 8 (opposite edges).
TEST(TetMass, EqualsTheClosedForms) {
  const double rho = 2700.0;
  for (int n : {4, 10}) {
    const auto x = element_nodes(n);
    const double V = tet_volume(x);
    const MatX M = tet_mass(x.data(), n, rho);
    MatX expected = MatX::Zero(3 * n, 3 * n);
    auto on_edge = [](int vertex, int e) { return kTet10Edges[e][0] == vertex || kTet10Edges[e][1] == vertex; };
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) {
        double m = 0.0;
        if (n == 4) {
          m = rho * V / 20.0 * (a == b ? 2.0 : 1.0);
        } else if (a < 4 && b < 4) {
          m = a == b ? 6.0 : 1.0;
        } else if (a < 4 || b < 4) {
          m = on_edge(std::min(a, b), std::max(a, b) - 4) ? -4.0 : -6.0;
        } else {
          const int e = a - 4, f = b - 4;
          const bool share = on_edge(kTet10Edges[e][0], f) || on_edge(kTet10Edges[e][1], f);
          m = e == f ? 32.0 : share ? 16.0 : 8.0;
        }
        if (n == 10) m *= rho * V / 420.0;
        for (int d = 0; d < 3; ++d) expected(3 * a + d, 3 * b + d) = m;
      }
    EXPECT_LT((M - expected).norm(), 1e-14 * expected.norm()) << n << " nodes";  // measured: at most 8.2e-16
  }
}

// The rules tet_mass integrates with: exact for every monomial xi^i eta^j zeta^k of their degree,
// against integral = i! j! k! / (i + j + k + 3)! on the unit tetrahedron.
TEST(TetMass, QuadratureRulesAreExactToTheirDegree) {
  auto factorial = [](int k) { return std::tgamma(k + 1.0); };
  for (int degree : {2, 5}) {
    const auto rule = tet_quadrature_rule(degree);
    EXPECT_EQ(rule.size(), degree == 2 ? 4u : 14u);
    for (int i = 0; i <= degree; ++i)
      for (int j = 0; i + j <= degree; ++j)
        for (int k = 0; i + j + k <= degree; ++k) {
          double sum = 0.0;
          for (const auto& [p, w] : rule) sum += w * std::pow(p.x(), i) * std::pow(p.y(), j) * std::pow(p.z(), k);
          const double exact = factorial(i) * factorial(j) * factorial(k) / factorial(i + j + k + 3);
          EXPECT_NEAR(sum, exact, 1e-14 * exact)
              << degree << ": " << i << " " << j << " " << k;  // measured: at most 7.3e-16
        }
  }
}

TEST(ElasticityMatrix, UniaxialStressGivesYoungsModulusAndPoisson) {
  // Under sigma_xx = 1 only, eps_xx = 1/E and eps_yy = -nu/E (inverse of D).
  const Vec6 eps = elasticity_matrix(kSteel).inverse() * (Vec6() << 1, 0, 0, 0, 0, 0).finished();
  EXPECT_NEAR(eps(0), 1.0 / 210e9, 1e-12 / 210e9);
  EXPECT_NEAR(eps(1), -0.3 / 210e9, 1e-12 / 210e9);
  EXPECT_NEAR(von_mises((Vec6() << 0, 0, 0, 0, 0, 2.0).finished()), 2.0 * std::sqrt(3.0), 1e-12);
}

TEST(Assembly, RigidMotionOfWholeLinkGivesZeroReaction) {
  for (bool quadratic : {false, true}) {
    TetMesh mesh = make_box_mesh(Vec3::Zero(), Vec3(0.2, 0.02, 0.03), 6, 2, 2);
    if (quadratic) mesh = to_quadratic(mesh);
    ASSERT_TRUE(validate(mesh).ok());
    const DofMap map = free_dof_map(mesh);
    solver::SparseMatrix K;
    ASSERT_TRUE(assemble_stiffness(mesh, {elasticity_matrix(kSteel)}, {}, map, &K).ok());
    const solver::SparseMatrix full = solver::SparseMatrix(K.selfadjointView<Eigen::Lower>());
    EXPECT_EQ(full.rows(), 3 * mesh.num_nodes());
    for (int m = 0; m < 6; ++m) {
      Vec6 q = Vec6::Zero();
      q(m) = m < 3 ? 1e-3 : 1e-2;
      VecX u(full.rows());
      for (int a = 0; a < mesh.num_nodes(); ++a) u.segment<3>(3 * a) = rigid_transfer(mesh.nodes[a]).topRows<3>() * q;
      // Reaction relative to a unit-strain-sized force scale ||K|| ||u||.
      EXPECT_LT((full * u).norm(), 1e-10 * full.norm() * u.norm()) << "mode " << m << " quadratic " << quadratic;
    }
  }
}

// The compressed-column assembly against the definition, densely: K = sum_e T_e^T K_e T_e with T the
// dof map (clamped dofs dropped, a coupled face following the reference node), on a small bar whose
// elements carry two materials; the pattern must be the sorted lower triangle CHOLMOD reads.
TEST(Assembly, CompressedColumnsEqualDenseSumOfElementMatrices) {
  for (bool quadratic : {false, true}) {
    TetMesh mesh = make_box_mesh(Vec3::Zero(), Vec3(0.2, 0.02, 0.03), 5, 2, 2);
    if (quadratic) mesh = to_quadratic(mesh);
    std::vector<int> clamped, coupled;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      if (mesh.nodes[n].x() < 1e-9) clamped.push_back(n);
      if (mesh.nodes[n].x() > 0.2 - 1e-9) coupled.push_back(n);
    }
    const Vec3 point(0.2, 0.001, -0.002);
    const DofMap map = make_dof_map(mesh, clamped, coupled, point);
    const std::vector<Mat6> D = {elasticity_matrix(kSteel),
                                 elasticity_matrix(Material::from_E_nu("stiff", 1e3 * 210e9, 0.3))};
    std::vector<int> material(mesh.num_elements());
    for (int e = 0; e < mesh.num_elements(); ++e) material[e] = e % 3 == 0;
    solver::SparseMatrix K;
    const Status s = assemble_stiffness(mesh, D, material, map, &K);
    ASSERT_TRUE(s.ok()) << s.message();
    ASSERT_TRUE(K.isCompressed());
    for (int j = 0; j < K.outerSize(); ++j)
      for (int k = K.outerIndexPtr()[j]; k < K.outerIndexPtr()[j + 1]; ++k) {
        ASSERT_GE(K.innerIndexPtr()[k], j) << "column " << j;
        if (k > K.outerIndexPtr()[j]) {
          ASSERT_GT(K.innerIndexPtr()[k], K.innerIndexPtr()[k - 1]) << "column " << j;
        }
      }
    // T: mesh dofs -> reduced dofs, from the rigid coupling u = u_ref + theta x (x - point).
    MatX T = MatX::Zero(3 * mesh.num_nodes(), map.num_dofs);
    int next = 0;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      if (std::find(clamped.begin(), clamped.end(), n) != clamped.end()) continue;
      if (std::find(coupled.begin(), coupled.end(), n) != coupled.end())
        T.block<3, 6>(3 * n, map.num_dofs - 6) = rigid_transfer(mesh.nodes[n] - point).topRows<3>();
      else
        T.block<3, 3>(3 * n, 3 * next++).setIdentity();
    }
    ASSERT_EQ(3 * next + 6, map.num_dofs);
    MatX Kmesh = MatX::Zero(3 * mesh.num_nodes(), 3 * mesh.num_nodes());
    std::array<Vec3, 10> x;
    for (int e = 0; e < mesh.num_elements(); ++e) {
      const int* v = mesh.element(e);
      for (int a = 0; a < mesh.nodes_per_element; ++a) x[a] = mesh.nodes[v[a]];
      const MatX Ke = tet_stiffness(x.data(), mesh.nodes_per_element, D[material[e]]);
      for (int a = 0; a < mesh.nodes_per_element; ++a)
        for (int b = 0; b < mesh.nodes_per_element; ++b)
          Kmesh.block<3, 3>(3 * v[a], 3 * v[b]) += Ke.block<3, 3>(3 * a, 3 * b);
    }
    const MatX expected = T.transpose() * Kmesh * T;
    const MatX assembled = MatX(solver::SparseMatrix(K.selfadjointView<Eigen::Lower>()));
    EXPECT_LT((assembled - expected).norm(), 1e-13 * expected.norm()) << "quadratic " << quadratic;

    // The mass on the same map, from the same code: the same pattern, the same definition.
    const std::vector<double> density = {7850.0, 2700.0};
    solver::SparseMatrix M;
    ASSERT_TRUE(assemble_mass(mesh, density, material, map, &M).ok());
    ASSERT_EQ(M.nonZeros(), K.nonZeros());
    EXPECT_TRUE(std::equal(M.innerIndexPtr(), M.innerIndexPtr() + M.nonZeros(), K.innerIndexPtr()));
    MatX Mmesh = MatX::Zero(3 * mesh.num_nodes(), 3 * mesh.num_nodes());
    for (int e = 0; e < mesh.num_elements(); ++e) {
      const int* v = mesh.element(e);
      for (int a = 0; a < mesh.nodes_per_element; ++a) x[a] = mesh.nodes[v[a]];
      const MatX Me = tet_mass(x.data(), mesh.nodes_per_element, density[material[e]]);
      for (int a = 0; a < mesh.nodes_per_element; ++a)
        for (int b = 0; b < mesh.nodes_per_element; ++b)
          Mmesh.block<3, 3>(3 * v[a], 3 * v[b]) += Me.block<3, 3>(3 * a, 3 * b);
    }
    const MatX expected_mass = T.transpose() * Mmesh * T;
    const MatX assembled_mass = MatX(solver::SparseMatrix(M.selfadjointView<Eigen::Lower>()));
    // Measured: at most 2.9e-16.
    EXPECT_LT((assembled_mass - expected_mass).norm(), 1e-13 * expected_mass.norm()) << "quadratic " << quadratic;
  }
}

TEST(Mesh, BoxMeshHasTheBoxVolumeAndQuadraticNodeCount) {
  const TetMesh mesh = make_box_mesh(Vec3::Zero(), Vec3(0.2, 0.02, 0.03), 5, 2, 3);
  EXPECT_EQ(mesh.num_elements(), 6 * 5 * 2 * 3);
  double volume = 0.0;
  for (int e = 0; e < mesh.num_elements(); ++e) volume += element_volume(mesh, e);
  EXPECT_NEAR(volume, 0.2 * 0.02 * 0.03, 1e-15);
  // A structured grid's quadratic version is the grid of half the spacing plus the cell-diagonal
  // midpoints: (2nx+1)(2ny+1)(2nz+1) nodes (every midpoint of the Kuhn split lies on that grid).
  EXPECT_EQ(to_quadratic(mesh).num_nodes(), 11 * 5 * 7);
}

TEST(Mesh, InvertedElementIsReported) {
  TetMesh mesh = make_box_mesh(Vec3::Zero(), Vec3::Ones(), 1, 1, 1);
  std::swap(mesh.connectivity[2], mesh.connectivity[3]);
  const Status s = validate(mesh);
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_NE(s.message().find("element 0"), std::string::npos) << s.message();
}

}  // namespace
}  // namespace kinestat::fea
