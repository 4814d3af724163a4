// Second-order (P-Delta) analysis (msa::solve_second_order): a cantilever column under an axial
// load and a small lateral one against the closed-form amplified deflection, in compression and in
// tension, the base moment H L + P delta of the deformed equilibrium, a beam-column pinned by end
// releases, and the refusals (a load above Euler's, regularization).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "beam_line.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/msa/buckling.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kL = 2.0;    // m
constexpr double kH = 100.0;  // N, lateral (global y) at the tip

// A cantilever along x clamped at node 0, in n beams, with the axial force P at the tip (N, positive
// in tension: +x) and the lateral H along y: bending in the x-y plane, about local z (the 20 x 30 mm
// rectangle's weak axis).
Structure cantilever(int n, double P) {
  Structure s = straight(kL, n, rectangle_section(0.02, 0.03));
  s.add_support({0, kAllDofs, Mat3::Identity()});
  LoadCase lc{.name = "P and H"};
  Vec6 w = Vec6::Zero();
  w(0) = P;
  w(1) = kH;
  lc.loads.push_back({n, w});
  s.add_load_case(lc);
  return s;
}

double EIz() { return kSteel.E * rectangle_section(0.02, 0.03).Iz; }
double euler_load() { return kPi * kPi * EIz() / (4 * kL * kL); }  // fixed-free, K = 2

// Tip deflection of a cantilever with tip lateral H and axial P (Timoshenko & Gere, Theory of
// Elastic Stability, sec. 1.11): compression, k = sqrt(|P|/EI): H (tan kL - kL) / (k^3 EI); tension:
// H (kL - tanh kL) / (k^3 EI). Both tend to H L^3 / (3 EI) as P -> 0.
double exact_tip_deflection(double P) {
  const double k = std::sqrt(std::abs(P) / EIz());
  const double kl = k * kL;
  return P < 0 ? kH * (std::tan(kl) - kl) / (k * k * k * EIz()) : kH * (kl - std::tanh(kl)) / (k * k * k * EIz());
}

Solution second_order(const Structure& s) {
  const Solution sol = solve_second_order(s);
  EXPECT_TRUE(sol.status.ok()) << sol.status.message();
  EXPECT_TRUE(sol.second_order.has_value());
  return sol;
}

struct AmplificationCase {
  double ratio;  // P / P_cr (Euler's fixed-free load), negative in compression
  const char* name;
  double error16;  // measured relative error of the tip deflection with n = 16 (see below)
};

class CantileverAmplification : public ::testing::TestWithParam<AmplificationCase> {};

// The P-Delta solution with the consistent K_G of cubic elements converges to the exact beam-column
// deflection as h^4 from below. Measured relative errors of the tip deflection (GCC 12 -O3, CHOLMOD):
//   P = -0.5 Pcr  n = 4: -1.63e-5  8: -1.03e-6  16: -6.42e-8  (amplification 2.0 of the linear 0.0633 m)
//   P = -0.9 Pcr  n = 4: -2.65e-4  8: -1.67e-5  16: -1.04e-6  (amplification 9.9)
//   P = +0.5 Pcr  n = 4: -5.45e-6  8: -3.46e-7  16: -2.17e-8
//   P = +2.0 Pcr  n = 4: -4.48e-5  8: -2.88e-6  16: -1.81e-7
// Each halving divides the error by 15.8 to 16.0: asserted 12..20; the n = 16 error is asserted
// below twice its measured value and negative (round-off, ~1e-12 here, is far below).
TEST_P(CantileverAmplification, TipDeflectionConvergesToBeamColumnClosedForm) {
  const AmplificationCase c = GetParam();
  const double P = c.ratio * euler_load();
  const double exact = exact_tip_deflection(P);
  double previous = 0.0;
  for (int n : {4, 8, 16}) {
    const Solution sol = second_order(cantilever(n, P));
    ASSERT_TRUE(sol.status.ok());
    const double err = (sol.cases[0].displacement[n](1) - exact) / exact;
    std::printf("%s n = %d: tip deflection relative error %.2e, %d iterations\n", c.name, n, err,
                sol.second_order->iterations[0]);
    EXPECT_LT(err, 0.0) << "n = " << n;
    if (previous != 0.0) {
      EXPECT_GT(previous / err, 12.0) << "n = " << n;
      EXPECT_LT(previous / err, 20.0) << "n = " << n;
    }
    if (n == 16) {
      EXPECT_LT(std::abs(err), 2.0 * c.error16);
    }
    previous = err;
  }
}

INSTANTIATE_TEST_SUITE_P(SecondOrder, CantileverAmplification,
                         ::testing::Values(AmplificationCase{-0.5, "compression_half_euler", 6.42e-8},
                                           AmplificationCase{-0.9, "compression_0_9_euler", 1.04e-6},
                                           AmplificationCase{0.5, "tension_half_euler", 2.17e-8},
                                           AmplificationCase{2.0, "tension_twice_euler", 1.81e-7}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SecondOrder, TensionStiffensCompressionSoftens) {
  const int n = 8;
  const double linear = kH * kL * kL * kL / (3 * EIz());
  const Solution lin = solve(cantilever(n, 0.5 * euler_load()));
  ASSERT_TRUE(lin.status.ok());
  // The linear solve ignores the axial force: H L^3 / 3EI to round-off (measured 1e-15 relative).
  EXPECT_NEAR(lin.cases[0].displacement[n](1), linear, 1e-12 * linear);
  const double pulled = second_order(cantilever(n, 0.5 * euler_load())).cases[0].displacement[n](1);
  const double pushed = second_order(cantilever(n, -0.5 * euler_load())).cases[0].displacement[n](1);
  std::printf("tip deflection / linear: tension %.4f, compression %.4f\n", pulled / linear, pushed / linear);
  // Measured 0.6708 in tension, 1.9863 in compression (the closed forms to 1e-6; the amplification
  // 1 / (1 - P/Pcr) = 2 is the first-mode estimate): on each side of the linear deflection by far.
  EXPECT_LT(pulled, 0.7 * linear);
  EXPECT_GT(pushed, 1.9 * linear);
}

TEST(SecondOrder, BaseMomentIsThatOfTheDeformedEquilibrium) {
  // K_G u of each beam has the moment N (v2 - v1), so the reactions balance the loads on the
  // deflected column: the base moment is H L - P v_tip exactly (to round-off), the P-Delta moment
  // included, whatever the discretization. Measured 5e-13 relative with n = 16: asserted 1e-11.
  for (double ratio : {-0.9, 0.5}) {
    const int n = 16;
    const double P = ratio * euler_load();
    const Solution sol = second_order(cantilever(n, P));
    ASSERT_TRUE(sol.status.ok());
    const double v = sol.cases[0].displacement[n](1);
    const double M = kH * kL - P * v;
    EXPECT_NEAR(-sol.cases[0].reaction[0](5), M, 1e-11 * kH * kL) << "P/Pcr " << ratio;
    EXPECT_NEAR(-sol.cases[0].reaction[0](0), P, 1e-9 * std::abs(P));
    // The checked resultant (loads, reactions and the P-Delta forces -K_G u) is round-off.
    EXPECT_LT(sol.cases[0].equilibrium_error, 1e-12);
    EXPECT_LT(sol.cases[0].free_dof_residual, 1e-10);
    // The end forces (k + k_G) T u hold the P-Delta moment too: on the first beam at the base acts the
    // support's moment, the reaction -(H L - P v).
    EXPECT_NEAR(sol.cases[0].beam_end_forces[0](5), -M, 1e-9 * M);
    EXPECT_NEAR(sol.second_order->axial_force[0][0], P, 1e-9 * std::abs(P));
  }
}

TEST(SecondOrder, AboveEulerLoadIsRefused) {
  // 1.05 Pcr: K + K_G is indefinite; the linear system has a solution (deflecting against H), which
  // is no equilibrium a column reaches: refused (a load with no equilibrium, as the loaded VJM's:
  // kNotConverged, exit 2) with what to do.
  const Solution sol = solve_second_order(cantilever(8, -1.05 * euler_load()));
  EXPECT_EQ(sol.status.code(), StatusCode::kNotConverged);
  EXPECT_NE(sol.status.message().find("critical (buckling) load"), std::string::npos) << sol.status.message();
  EXPECT_TRUE(sol.cases.empty());
  // Just below (0.98 Pcr: amplification 50) it converges.
  const Solution near = solve_second_order(cantilever(8, -0.98 * euler_load()));
  EXPECT_TRUE(near.status.ok()) << near.status.message();
}

TEST(SecondOrder, IterationLimitGivesNotConverged) {
  // One iteration cannot show a change below the tolerance (the first one moves from the linear
  // displacements by the amplification, 100 %).
  SecondOrderOptions opt;
  opt.max_iterations = 1;
  const Solution sol = solve_second_order(cantilever(4, -0.5 * euler_load()), opt);
  EXPECT_EQ(sol.status.code(), StatusCode::kNotConverged);
  EXPECT_NE(sol.status.message().find("did not converge in 1 iterations"), std::string::npos) << sol.status.message();
}

TEST(SecondOrder, AxialForcesAreIterated) {
  // A portal frame (two 3 m columns, a 4 m beam, clamped feet) under gravity loads on the corners
  // and a sway load: the sway moves axial force from one column to the other, so N changes from the
  // linear solve's and the iteration takes more than two solves; it converges to the tolerance and
  // the deformed equilibrium holds. Measured: 4 iterations, sway 36.1 mm against 31.8 mm linear,
  // N = -9304 N and -10696 N in the columns.
  Structure s;
  const int m = s.add_material(kSteel);
  const int c = s.add_section(rectangle_section(0.05, 0.05));
  s.add_node("a", Vec3(0, 0, 0));
  s.add_node("b", Vec3(0, 0, 3));
  s.add_node("c", Vec3(4, 0, 3));
  s.add_node("d", Vec3(4, 0, 0));
  s.add_beam(make_beam("left", 0, 1, m, c));
  s.add_beam(make_beam("top", 1, 2, m, c));
  s.add_beam(make_beam("right", 3, 2, m, c));
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_support({3, kAllDofs, Mat3::Identity()});
  LoadCase lc{.name = "gravity and sway"};
  lc.loads.push_back({1, (Vec6() << 2000, 0, -10000, 0, 0, 0).finished()});
  lc.loads.push_back({2, (Vec6() << 0, 0, -10000, 0, 0, 0).finished()});
  s.add_load_case(lc);
  const Solution lin = solve(s);
  const Solution sol = second_order(s);
  ASSERT_TRUE(sol.status.ok() && lin.status.ok());
  const double sway = sol.cases[0].displacement[1](0), sway_lin = lin.cases[0].displacement[1](0);
  std::printf("portal: %d iterations, change %.1e, sway %.4e m (linear %.4e), N left %.1f right %.1f\n",
              sol.second_order->iterations[0], sol.second_order->relative_change[0], sway, sway_lin,
              sol.second_order->axial_force[0][0], sol.second_order->axial_force[0][2]);
  EXPECT_GT(sol.second_order->iterations[0], 2);
  EXPECT_LE(sol.second_order->relative_change[0], SecondOrderOptions{}.tolerance);
  EXPECT_GT(sway, sway_lin);  // compressed columns sway more
  EXPECT_LT(sol.cases[0].equilibrium_error, 1e-12);
  // Vertical equilibrium: the columns carry the 20 kN between them.
  EXPECT_NEAR(sol.second_order->axial_force[0][0] + sol.second_order->axial_force[0][2], -20000.0, 1e-9 * 2e4);
}

// A pinned-pinned beam-column made by end releases (beam_line.hpp, pinned_by_releases), compressed by
// P = P_E / 2 with a lateral Q at midspan: the midspan deflection is Q (tan u - u) / (2 P k),
// k = sqrt(P / EI), u = k L / 2 (Timoshenko & Gere, Theory of Elastic Stability, ch. 1, the
// beam-column under a concentrated load), twice the linear Q L^3 / (48 EI). The released beams'
// K_G is condensed with their released dofs' static shapes. Eight beams: measured -1.65e-5 from the
// closed form; asserted within twice that.
TEST(SecondOrder, BeamColumnPinnedByEndReleases) {
  const Section sec = rectangle_section(0.02, 0.03);
  const int n = 8;
  const double EI = kSteel.E * sec.Iz, P = 0.5 * kPi * kPi * EI / (kL * kL), Q = 100.0;
  Structure s = pinned_by_releases(kL, n, sec);
  LoadCase lc{.name = "P and Q"};
  lc.loads.push_back({n, Vec6::Unit(0) * -P});
  lc.loads.push_back({n / 2, Vec6::Unit(1) * Q});
  s.add_load_case(lc);
  const Solution sol = solve_second_order(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const double k = std::sqrt(P / EI), u = k * kL / 2;
  const double exact = Q * (std::tan(u) - u) / (2 * P * k);
  const double mid = sol.cases[0].displacement[n / 2](1);
  std::printf("beam-column pinned by releases: midspan %.6e m, closed form %.6e (%+.2e), linear %.6e\n", mid, exact,
              mid / exact - 1, Q * kL * kL * kL / (48 * EI));
  EXPECT_NEAR(mid, exact, 2.0 * 1.65e-5 * exact);
  // The released end moments stay zero; the axial force is -P in every beam.
  EXPECT_NEAR(sol.cases[0].beam_end_forces[0](5), 0.0, 1e-9 * Q * kL);
  EXPECT_NEAR(sol.cases[0].beam_end_forces[n - 1](11), 0.0, 1e-9 * Q * kL);
  for (double N : sol.second_order->axial_force[0]) EXPECT_NEAR(N, -P, 1e-9 * P);
}

TEST(SecondOrder, RegularizationAndBadOptionsAreRefused) {
  Structure s = cantilever(2, -1000.0);
  SolveOptions reg;
  reg.regularize = true;
  const Solution g = solve_second_order(s, {}, reg);
  EXPECT_EQ(g.status.code(), StatusCode::kInvalidInput);
  SecondOrderOptions bad;
  bad.tolerance = 0.0;
  EXPECT_EQ(solve_second_order(s, bad).status.code(), StatusCode::kInvalidInput);
}

}  // namespace
}  // namespace kinestat::msa
