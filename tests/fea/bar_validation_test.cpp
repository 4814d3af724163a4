// A prismatic bar clamped at x = 0, reference at x = L: the FEA 6x6 against the Timoshenko
// cantilever (an independent route: elements/beam_element.hpp with the exact Saint-Venant torsion
// constant of the rectangle).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/mesh_convergence.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {
namespace {

const Material kSteel = Material::from_E_nu("steel", 210e9, 0.3);
constexpr double L = 0.2, b = 0.02, h = 0.03;  // length (x), width (y), height (z), m

// Tip compliance of the Timoshenko cantilever: inverse of the free-end block of the beam matrix.
Mat6 timoshenko_cantilever_compliance() {
  const Mat12 K = beam_local_stiffness(kSteel, rectangle_section(b, h), L, BeamTheory::kTimoshenko);
  return K.bottomRightCorner<6, 6>().inverse();
}

LinkStiffnessOptions bar_options() {
  LinkStiffnessOptions o;
  o.clamp = Region::plane(Vec3::Zero(), Vec3::UnitX());
  o.reference = Region::plane(Vec3(L, 0, 0), Vec3::UnitX());
  o.reference_point = Vec3(L, 0, 0);
  o.keep_fields = false;
  return o;
}

// Bar of n cells along y (the 20 mm side): cells ~b/n cubes-ish.
TetMesh bar_mesh(int n, bool quadratic) {
  TetMesh m = make_box_mesh(Vec3(0, -b / 2, -h / 2), Vec3(L, b / 2, h / 2), 10 * n, n, (3 * n + 1) / 2);
  return quadratic ? to_quadratic(m) : m;
}

// Relative error of the diagonal compliances (ux uy uz rx ry rz) against the beam.
Vec6 diagonal_error(const Mat6& C) {
  const Mat6 ref = timoshenko_cantilever_compliance();
  return (C.diagonal() - ref.diagonal()).cwiseQuotient(ref.diagonal());
}

// Cells of about h = b/n along every axis: n = 1, 2, 4 give 861, 4101, 27735 dofs.
TEST(BarValidation, QuadraticTetsMatchTimoshenkoWithin2PercentAndConverge) {
  const Mat6 ref = timoshenko_cantilever_compliance();
  auto study = mesh_convergence_study(
      [](double size) -> StatusOr<TetMesh> { return bar_mesh(static_cast<int>(std::lround(b / size)), true); },
      {b, b / 2, b / 4}, kSteel, bar_options());
  ASSERT_TRUE(study.ok()) << study.status().message();
  std::vector<Vec6> errors;
  for (const Mat6& C : study->compliance) {
    errors.push_back(diagonal_error(C));
    EXPECT_LT(scaled_symmetry_error(C), 1e-6);
    EXPECT_LT(scaled_symmetry_error(C.inverse()), 1e-6);
  }
  const Mat6& finest = study->compliance.back();
  for (int k = 0; k < 6; ++k) {
    // The error drops under refinement...
    EXPECT_LT(std::abs(errors[1](k)), std::abs(errors[0](k))) << "dof " << k;
    EXPECT_LT(std::abs(errors[2](k)), std::abs(errors[1](k))) << "dof " << k;
    // ... to within 2 % of beam theory. What is left is not discretization but 3D effects the beam
    // ignores: the clamped face and the rigid reference face stop the Poisson contraction and the
    // torsional warping of the end sections, so the solid is slightly stiffer (all errors are
    // negative: -0.8 % axial, -1.1/-0.9 % bending, -1.9 % torsion at n = 4).
    EXPECT_LT(std::abs(errors[2](k)), 0.02) << "dof " << k << " error " << errors[2](k);
    EXPECT_LT(errors[2](k), 0.0) << "dof " << k;
    // Richardson: quadratic elements converge at an observed order near 2 in energy-like
    // quantities; the extrapolated limit stays within 2 % of the beam too (-1.2 % in torsion).
    ASSERT_TRUE(study->diagonal[k].ok()) << study->diagonal[k].status().message();
    const RichardsonEstimate& est = *study->diagonal[k];
    EXPECT_GT(est.order, 1.0) << "dof " << k;
    EXPECT_NEAR(est.extrapolated / ref(k, k), 1.0, 0.02) << "dof " << k;
    EXPECT_LT(std::abs(est.finest_error), 0.01) << "dof " << k;
  }
  // Bending-rotation couplings (the cantilever's L^2 / 2EI terms, opposite signs in the two planes).
  EXPECT_NEAR(finest(1, 5) / ref(1, 5), 1.0, 0.02);
  EXPECT_NEAR(finest(2, 4) / ref(2, 4), 1.0, 0.02);
  // Terms the bar's double symmetry makes zero are small. Not round-off: the Kuhn split is not
  // mirror-symmetric, so they are discretization errors (~1e-4 of the diagonal at n = 4).
  EXPECT_LT(std::abs(finest(0, 1)), 1e-3 * std::sqrt(finest(0, 0) * finest(1, 1)));
  EXPECT_LT(std::abs(finest(3, 4)), 1e-3 * std::sqrt(finest(3, 3) * finest(4, 4)));
  std::cout << convergence_report(*study);
}

// Linear tetrahedra have constant strain: a bent element cannot represent the linear strain
// through its depth and locks in shear, so on the same grid the bending compliance is far too
// small. This is why the quadratic element is the default.
TEST(BarValidation, LinearTetsLockInBending) {
  auto linear = link_stiffness(bar_mesh(2, false), kSteel, bar_options());
  auto quadratic = link_stiffness(bar_mesh(2, true), kSteel, bar_options());
  ASSERT_TRUE(linear.ok() && quadratic.ok());
  const Vec6 e_lin = diagonal_error(linear->cartesian.compliance);
  const Vec6 e_quad = diagonal_error(quadratic->cartesian.compliance);
  EXPECT_LT(e_lin(1), -0.25) << "linear tets, bending about z";
  EXPECT_LT(e_lin(2), -0.25) << "linear tets, bending about y";
  EXPECT_GT(e_quad(1), -0.02);
  // Refining the linear mesh helps only slowly (first order in bending).
  auto finer = link_stiffness(bar_mesh(4, false), kSteel, bar_options());
  ASSERT_TRUE(finer.ok());
  const Vec6 e_fine = diagonal_error(finer->cartesian.compliance);
  EXPECT_LT(std::abs(e_fine(1)), std::abs(e_lin(1)));
  EXPECT_LT(e_fine(1), -0.05) << "still locked at 4 cells across";
}

// The paper's pseudo-rigid body (an end cap 100x stiffer, 1000x, ...) tends to the exact rigid
// coupling; the gap shrinks in proportion to 1 / ratio (the cap's own compliance) as long as that
// gap is larger than the round-off, which grows with the ratio (the cap multiplies the condition
// number of K). Measured here (largest relative gap of the diagonal, printed by this test with
// OPENBLAS_NUM_THREADS=1 and 2): 6.5e-4, 6.5e-5, 6.6e-6, 6.5e-7 at 1e2..1e5, all torsion and
// identical to 1e-3 across runs; from 1e6 on the bending entries are round-off that changes with
// BLAS threads and CPU: 2.8e-6 to 6.9e-6 at 1e6 (1.5e-5 to 2.0e-5 at 1e7, 2.4e-4 to 3.9e-4 at 1e8
// with those ratios added to the list). On CI's CPU a bound of 1e-5 at 1e6 failed. So 1e6 is
// computed and printed, not asserted: a bound on round-off that varies by CPU guards nothing (docs/
// fea.md: 1e4 to 1e5 is the useful range). What is asserted is the 1 / ratio law on the torsion
// entry, the largest gap and the one round-off does not reach before 1e6: each decade's ratio of
// gaps within 0.5 of 10 (printed; the gaps repeat to 1e-3 between runs), and the gap at 1e5 below
// 1e-6 (measured 6.5e-7).
TEST(BarValidation, StiffBodyConvergesToRigidCoupling) {
  const double t = L / 10;  // cap length
  const TetMesh mesh = to_quadratic(make_box_mesh(Vec3(0, -b / 2, -h / 2), Vec3(L + t, b / 2, h / 2), 22, 2, 3));
  LinkStiffnessOptions o = bar_options();
  auto rigid = link_stiffness(mesh, kSteel, o);
  ASSERT_TRUE(rigid.ok()) << rigid.status().message();
  o.reference_model = ReferenceModel::kStiffBody;
  o.reference = Region::box(Vec3(L, -b, -h), Vec3(L + t, b, h));
  std::vector<double> gaps;
  for (double ratio : {1e2, 1e3, 1e4, 1e5, 1e6}) {
    o.stiff_body_ratio = ratio;
    auto body = link_stiffness(mesh, kSteel, o);
    ASSERT_TRUE(body.ok()) << body.status().message();
    EXPECT_LT(body->compliance_symmetry_error, 1e-6);
    EXPECT_GT(body->num_stiff_elements, 0);
    // Largest relative gap over the diagonal entries; all six printed, for the figures above.
    const Vec6 gap = (body->cartesian.compliance.diagonal() - rigid->cartesian.compliance.diagonal())
                         .cwiseQuotient(rigid->cartesian.compliance.diagonal());
    std::cout << "ratio " << ratio << ": relative gap (ux uy uz rx ry rz) " << gap.transpose() << "\n";
    gaps.push_back(std::abs(gap(3)));  // torsion: the body's own compliance, not round-off
  }
  std::cout << "torsion gap ratios per decade: " << gaps[0] / gaps[1] << ", " << gaps[1] / gaps[2] << ", "
            << gaps[2] / gaps[3] << " (1e6, not asserted: " << gaps[4] << ")\n";
  EXPECT_NEAR(gaps[0] / gaps[1], 10.0, 0.5);
  EXPECT_NEAR(gaps[1] / gaps[2], 10.0, 0.5);
  EXPECT_NEAR(gaps[2] / gaps[3], 10.0, 0.5);
  EXPECT_LT(gaps[3], 1e-6);
}

TEST(BarValidation, EmptyOrOverlappingRegionsAreInvalidInput) {
  const TetMesh mesh = bar_mesh(1, true);
  LinkStiffnessOptions o = bar_options();
  o.clamp = Region::plane(Vec3(-1, 0, 0), Vec3::UnitX());
  auto r = link_stiffness(mesh, kSteel, o);
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(r.status().message().find("clamp region"), std::string::npos) << r.status().message();
  o = bar_options();
  o.reference = Region::box(Vec3(-1, -1, -1), Vec3(1, 1, 1));
  r = link_stiffness(mesh, kSteel, o);
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(r.status().message().find("both clamped and on the reference"), std::string::npos);
}

// A second solid beside the bar, which the clamp does not hold, moves freely: singular, said as
// a separate part (before, the factorization's free motion blamed the clamp region's nodes).
TEST(BarValidation, ASeparatePartWithoutClampIsSingularAndNamed) {
  TetMesh mesh = bar_mesh(1, false);
  const TetMesh other = make_box_mesh(Vec3(2 * L, -b / 2, -h / 2), Vec3(3 * L, b / 2, h / 2), 10, 1, 2);
  const int offset = mesh.num_nodes();
  mesh.nodes.insert(mesh.nodes.end(), other.nodes.begin(), other.nodes.end());
  for (int n : other.connectivity) mesh.connectivity.push_back(n + offset);
  const auto r = link_stiffness(mesh, kSteel, bar_options());
  EXPECT_EQ(r.status().code(), StatusCode::kSingular);
  EXPECT_NE(r.status().message().find("separate parts"), std::string::npos) << r.status().message();
  EXPECT_TRUE(link_stiffness(bar_mesh(1, false), kSteel, bar_options()).ok());
}

}  // namespace
}  // namespace kinestat::fea
