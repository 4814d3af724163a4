// The bundled models/ parse, and their solutions agree with hand calculations done here from the
// numbers written in the files (not from the code's output).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::io {
namespace {

std::string model(const std::string& name) { return std::string(KINESTAT_SOURCE_DIR) + "/models/" + name; }

msa::Structure load(const std::string& name) {
  auto r = read_structure_yaml(model(name));
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? std::move(r).value() : msa::Structure{};
}

const msa::LoadCaseResult* find_case(const msa::Solution& sol, const std::string& name) {
  for (const auto& c : sol.cases) {
    if (c.name == name) return &c;
  }
  ADD_FAILURE() << "no load case " << name;
  return nullptr;
}

// models/cantilever.yaml: L = 1 m, E = 210 GPa, nu = 0.3, rectangle b = 0.02 m (local y) x
// h = 0.04 m (local z), Euler-Bernoulli, clamped at A.
constexpr double kL = 1.0, kE = 210e9, kNu = 0.3, kB = 0.02, kH = 0.04;
constexpr double kG = kE / (2 * (1 + kNu));
constexpr double kA = kB * kH, kIy = kB * kH * kH * kH / 12, kIz = kH * kB * kB * kB / 12;
// Torsion constant J = beta h b^3 with beta = 0.229 for h/b = 2 (Timoshenko & Goodier, Theory of
// Elasticity, table for rectangular bars; three digits, hence the 0.2 % tolerance on the twist).
constexpr double kJ = 0.229 * kH * kB * kB * kB;

TEST(BundledModels, CantileverTipMatchesBeamTheory) {
  const msa::Structure s = load("cantilever.yaml");
  ASSERT_EQ(s.nodes().size(), 2u);
  const msa::Solution sol = msa::solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const int tip = *s.find_node("B");

  // P L^3 / (3 E I) for both bending planes, T L / (G J) for the twist.
  const auto* down = find_case(sol, "tip_down");
  ASSERT_NE(down, nullptr);
  const double w = -1000.0 * kL * kL * kL / (3 * kE * kIy);
  EXPECT_NEAR(down->displacement[tip](2), w, 1e-9 * std::abs(w));
  // Slope -P L^2 / (2 E I): the tip's rotation about +y is minus dw/dx.
  EXPECT_NEAR(down->displacement[tip](4), 1000.0 * kL * kL / (2 * kE * kIy), 1e-9 * 1000.0 / (kE * kIy));
  // The clamp carries the load: +1000 N up and the moment -1000 N m about y.
  const int root = *s.find_node("A");
  EXPECT_NEAR(down->reaction[root](2), 1000.0, 1e-6);
  EXPECT_NEAR(down->reaction[root](4), -1000.0, 1e-6);

  const auto* side = find_case(sol, "tip_sideways");
  ASSERT_NE(side, nullptr);
  const double v = 500.0 * kL * kL * kL / (3 * kE * kIz);
  EXPECT_NEAR(side->displacement[tip](1), v, 1e-9 * v);

  const auto* torque = find_case(sol, "tip_torque");
  ASSERT_NE(torque, nullptr);
  const double phi = 50.0 * kL / (kG * kJ);
  EXPECT_NEAR(torque->displacement[tip](3), phi, 2e-3 * phi);
}

TEST(BundledModels, CantileverCartesianComplianceIsTheTipFlexibility) {
  const msa::Structure s = load("cantilever.yaml");
  ASSERT_TRUE(s.report_node().has_value());
  const msa::Solution sol = msa::solve(s);
  ASSERT_TRUE(sol.cartesian.has_value());
  const Mat6& C = sol.cartesian->compliance;
  // Tip flexibility of a cantilever along x (ux uy uz rx ry rz):
  Mat6 expected = Mat6::Zero();
  expected(0, 0) = kL / (kE * kA);
  expected(1, 1) = kL * kL * kL / (3 * kE * kIz);
  expected(2, 2) = kL * kL * kL / (3 * kE * kIy);
  expected(3, 3) = kL / (kG * kJ);
  expected(4, 4) = kL / (kE * kIy);
  expected(5, 5) = kL / (kE * kIz);
  expected(1, 5) = expected(5, 1) = kL * kL / (2 * kE * kIz);
  expected(2, 4) = expected(4, 2) = -kL * kL / (2 * kE * kIy);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      const double tol = (i == 3 && j == 3) ? 2e-3 * expected(3, 3) : 1e-9 * std::abs(expected(i, j)) + 1e-20;
      EXPECT_NEAR(C(i, j), expected(i, j), tol) << i << "," << j;
    }
  }
  EXPECT_LE((C - C.transpose()).norm(), 1e-12 * C.norm());
}

// models/portal_frame.yaml (mm-N-s): columns H = 3 m, girder L = 4 m, SHS 100x100x5 everywhere,
// E = 210000 MPa, clamped feet.
TEST(BundledModels, PortalFrameSwayAndRoofLoad) {
  const msa::Structure s = load("portal_frame.yaml");
  ASSERT_EQ(s.nodes().size(), 4u);
  EXPECT_DOUBLE_EQ(s.nodes()[2].position.x(), 4.0);  // 4000 mm
  EXPECT_DOUBLE_EQ(s.materials()[0].E, 210e9);       // 210000 MPa
  const msa::Solution sol = msa::solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();

  const double E = 210e9, H = 3.0, L = 4.0;
  const double A = 0.1 * 0.1 - 0.09 * 0.09;                        // m^2
  const double I = (std::pow(0.1, 4) - std::pow(0.09, 4)) / 12.0;  // m^4, same for columns and girder
  const int B = *s.find_node("B"), C = *s.find_node("C");

  // Sway of a fixed-base portal by slope deflection (no axial deformation): with
  // k = (I_girder / L) / (I_column / H), the lateral stiffness is 24 E I / H^3 (1 + 6k) / (4 + 6k).
  // Finite EA can only add flexibility (compliance grows as stiffness drops); here it adds about
  // 0.15 % (girder shortening (P/2) L / EA = 5e-5 m against a 0.029 m sway, plus the columns'),
  // so the model's sway must lie in [formula, formula * 1.005].
  const auto* wind = find_case(sol, "wind");
  ASSERT_NE(wind, nullptr);
  const double k = (I / L) / (I / H);
  const double sway = 10000.0 / (24 * E * I / (H * H * H) * (1 + 6 * k) / (4 + 6 * k));
  EXPECT_GE(wind->displacement[B](0), sway * (1 - 1e-9));
  EXPECT_LE(wind->displacement[B](0), sway * 1.005);
  // The girder is (nearly) rigid axially: both corners sway alike.
  EXPECT_NEAR(wind->displacement[C](0), wind->displacement[B](0), 5e-3 * sway);
  // The feet carry the 10 kN together.
  const int Af = *s.find_node("A"), D = *s.find_node("D");
  EXPECT_NEAR(wind->reaction[Af](0) + wind->reaction[D](0), -10000.0, 1e-6);

  // Equal loads on the corners of a symmetric frame: each column carries 20 kN axially and the
  // girder only translates, so both corners drop by exactly P H / (E A).
  const auto* roof = find_case(sol, "roof");
  ASSERT_NE(roof, nullptr);
  const double drop = -20000.0 * H / (E * A);
  EXPECT_NEAR(roof->displacement[B](2), drop, 1e-9 * std::abs(drop));
  EXPECT_NEAR(roof->displacement[C](2), drop, 1e-9 * std::abs(drop));
  EXPECT_NEAR(roof->reaction[Af](2), 20000.0, 1e-6);
  EXPECT_NEAR(roof->reaction[D](2), 20000.0, 1e-6);
}

// models/released_chain.yaml: a revolute joint about z at x = 0.4 m with no spring; the second
// link (to the tip at x = 0.9 m) swings about it. Exactly one free motion: the hinge side H2 and
// the tip rotate about z by the same angle and the tip moves along y by 0.5 m times that angle.
TEST(BundledModels, ReleasedChainIsSingularWithTheSwingAsFreeMotion) {
  const msa::Structure s = load("released_chain.yaml");
  const msa::Solution sol = msa::solve(s);
  EXPECT_EQ(sol.status.code(), StatusCode::kSingular) << sol.status.message();
  EXPECT_TRUE(sol.cases.empty());
  ASSERT_TRUE(sol.singularity.singular);
  ASSERT_EQ(sol.singularity.modes.size(), 1u);
  EXPECT_FALSE(sol.singularity.weak_dofs.empty());
  const auto& m = sol.singularity.modes[0].node_motion;
  const int base = *s.find_node("base"), h1 = *s.find_node("H1"), h2 = *s.find_node("H2"), tip = *s.find_node("tip");
  const double theta = m[tip](5);  // the mode's scale is arbitrary: compare ratios
  ASSERT_GT(std::abs(theta), 1e-3);
  EXPECT_NEAR(m[tip](1), 0.5 * theta, 1e-6);
  EXPECT_NEAR(m[h2](5), theta, 1e-6);
  EXPECT_LT(m[base].norm(), 1e-6);
  EXPECT_LT(m[h1].norm(), 1e-6);
  EXPECT_LT(m[h2].head<3>().norm(), 1e-6);
}

// models/loaded_beam.yaml: L = 4 m simply supported, E = 210 GPa, rectangle 0.06 x 0.12 m (h
// vertical), density 7850 kg/m^3; w = 2000 N/m; alpha = 1.2e-5 /K, dTz = 20 K over hz = 0.12 m.
TEST(BundledModels, LoadedBeamMatchesBeamTheoryAlongTheSpan) {
  const msa::Structure s = load("loaded_beam.yaml");
  const msa::Solution sol = msa::solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const double L = 4.0, E = 210e9, A = 0.06 * 0.12, I = 0.06 * std::pow(0.12, 3) / 12, w = 2000.0;
  auto st = msa::all_beam_stations(s, sol, 5);  // x = 0, 1, 2, 3, 4 m
  ASSERT_TRUE(st.ok()) << st.status().message();
  const double tol = 1e-12;  // exact element and exact integration: round-off (measured ~1e-15)
  // Self-weight: q = rho A g, midspan 5 q L^4 / 384 EI downwards.
  const double q = 7850 * A * 9.81, self = 5 * q * std::pow(L, 4) / (384 * E * I);
  EXPECT_NEAR((*st)[0][0].displacement[2](2), -self, tol * self);
  // Uniform load: 5 w L^4 / 384 EI, sagging moment w L^2 / 8 (My = -EI w'' < 0), the extremes there.
  const double mid = 5 * w * std::pow(L, 4) / (384 * E * I);
  const msa::BeamStations& u = (*st)[1][0];
  EXPECT_NEAR(u.displacement[2](2), -mid, tol * mid);
  EXPECT_NEAR(u.forces[2](4), -w * L * L / 8, tol * w * L * L / 8);
  EXPECT_NEAR(u.extremes[6 + 2].min, -mid, tol * mid);
  EXPECT_EQ(u.extremes[6 + 2].x_at_min, 2.0);
  EXPECT_EQ(u.extremes[4].x_at_min, 2.0);
  // Point load P = 5000 N at a = 1 m plus a triangle 0 -> 1000 N/m over [2, 4] m: the reaction at A
  // is P (L - a)/L + (1000 * 2 / 2) * (L - 10/3)/L, with the triangle's resultant 4/3 m from B's side.
  const double RA = 5000 * 3.0 / 4 + 1000 * (4 - 10.0 / 3) / 4;
  EXPECT_NEAR(sol.cases[2].reaction[0](2), RA, tol * RA);
  // Moment at x = 1 m (at the point load): -RA * 1 m.
  EXPECT_NEAR((*st)[2][0].forces[1](4), -RA * 1.0, tol * RA);
  // Temperature: a free curvature alpha dTz / hz upwards, no force on a statically determinate beam:
  // midspan rise alpha dTz L^2 / (8 hz).
  const double rise = 1.2e-5 * 20 * L * L / (8 * 0.12);
  EXPECT_NEAR((*st)[3][0].displacement[2](2), rise, tol * rise);
  EXPECT_LT(sol.cases[3].reaction[0].norm(), 1e-6);
}

}  // namespace
}  // namespace kinestat::io
