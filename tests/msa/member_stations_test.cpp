// Along-member results (beam_stations): internal forces and the deflected shape at stations against
// the closed-form curves of textbook beams.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "beam_line.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::msa {
namespace {

// The stations of beam `beam` in case 0 compared with closed forms of x: component `dof` of the
// displacement or (forces = true) of the internal forces, to `rel` of the curve's largest value.
void expect_curve(const BeamStations& st, bool forces, int dof, const std::function<double(double)>& exact,
                  double rel) {
  double scale = 0.0;
  for (double x : st.x) scale = std::max(scale, std::abs(exact(x)));
  ASSERT_GT(scale, 0.0);
  for (size_t k = 0; k < st.x.size(); ++k) {
    const double got = forces ? st.forces[k](dof) : st.displacement[k](dof);
    EXPECT_NEAR(got, exact(st.x[k]), rel * scale)
        << (forces ? "force " : "displacement ") << dof << " at x = " << st.x[k];
  }
}

// Exact fields integrated exactly: round-off only (measured below 1e-14 of the largest value);
// 1e-12 leaves a margin of 100.
constexpr double kRel = 1e-12;

BeamStations stations(const Structure& s, const Solution& sol, int beam, int count) {
  auto st = beam_stations(s, s.load_cases()[0], sol.cases[0], beam, count);
  EXPECT_TRUE(st.ok()) << st.status().message();
  return st.ok() ? *st : BeamStations{};
}

TEST(MemberStations, SimplySupportedBeamDeflectionMomentAndShear) {
  const Section sec = rectangle_section(0.04, 0.08);
  const double L = 3.0, q = 2500.0;  // one element, load -q along z
  Structure s = straight(L, 1, sec);
  s.add_support({0, {true, true, true, true, false, false}, Mat3::Identity()});
  s.add_support({1, {false, true, true, false, false, false}, Mat3::Identity()});
  MemberLoad ml;
  ml.beam = 0;
  ml.global_axes = true;
  ml.w1 = Vec3(0, 0, -q);
  s.add_load_case({.name = "udl", .member_loads = {ml}});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const BeamStations st = stations(s, sol, 0, 9);
  ASSERT_EQ(st.x.size(), 9u);
  const double EI = kSteel.E * sec.Iy;
  // w(x) = -q x (L^3 - 2 L x^2 + x^3) / (24 EI): 5 q L^4 / 384 EI at midspan.
  expect_curve(
      st, false, 2, [&](double x) { return -q * x * (L * L * L - 2 * L * x * x + x * x * x) / (24 * EI); }, kRel);
  EXPECT_NEAR(st.displacement[4](2), -5 * q * L * L * L * L / (384 * EI), kRel * 5 * q * L * L * L * L / (384 * EI));
  // ry = -dw/dx.
  expect_curve(
      st, false, 4, [&](double x) { return q * (L * L * L - 6 * L * x * x + 4 * x * x * x) / (24 * EI); }, kRel);
  // My = -q x (L - x) / 2 (sagging: -EI w''), q L^2 / 8 at midspan; Vz = q (x - L/2).
  expect_curve(
      st, true, 4, [&](double x) { return -q * x * (L - x) / 2; }, kRel);
  EXPECT_NEAR(st.forces[4](4), -q * L * L / 8, kRel * q * L * L / 8);
  expect_curve(
      st, true, 2, [&](double x) { return q * (x - L / 2); }, kRel);
  // The ends agree with the end forces: x = L is end 2, x = 0 the negated end 1.
  EXPECT_LT((st.forces[8] - sol.cases[0].beam_end_forces[0].tail<6>()).norm(), kRel * q * L * L);
  EXPECT_LT((st.forces[0] + sol.cases[0].beam_end_forces[0].head<6>()).norm(), kRel * q * L * L);
}

TEST(MemberStations, CantileverUnderSelfWeightAlongItsLength) {
  const Section sec = circle_section(0.05);
  const double L = 2.0, g = 9.81;
  Structure s = straight(L, 1, sec);
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_load_case({.name = "weight", .gravity = Vec3(0, 0, -g)});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const BeamStations st = stations(s, sol, 0, 7);
  const double q = kSteel.density * sec.A * g, EI = kSteel.E * sec.Iy;
  expect_curve(
      st, false, 2, [&](double x) { return -q * x * x * (6 * L * L - 4 * L * x + x * x) / (24 * EI); }, kRel);
  expect_curve(
      st, false, 4, [&](double x) { return q * x * (3 * L * L - 3 * L * x + x * x) / (6 * EI); }, kRel);
  // Hogging moment My = q (L - x)^2 / 2 on the +x face (-EI w'' with w'' < 0), shear Vz = -q (L - x).
  expect_curve(
      st, true, 4, [&](double x) { return q * (L - x) * (L - x) / 2; }, kRel);
  expect_curve(
      st, true, 2, [&](double x) { return -q * (L - x); }, kRel);
}

TEST(MemberStations, TimoshenkoCantileverWithAPointLoadOnTheSpan) {
  // A stocky cantilever (Phi ~ 0.5) with P along +y at a: v(x) = P x^2 (3a - x)/(6EI) + P x/(G As)
  // up to a, then a straight line with the slope of the cross-section at a (no shear beyond a).
  const Section sec = rectangle_section(0.2, 0.3);
  const double L = 0.8, a = 0.5, P = 20000.0;
  Structure s = straight(L, 1, sec, BeamTheory::kTimoshenko);
  s.add_support({0, kAllDofs, Mat3::Identity()});
  MemberLoad ml;
  ml.beam = 0;
  ml.type = MemberLoadType::kPoint;
  ml.a = a;
  ml.force = Vec3(0, P, 0);
  s.add_load_case({.name = "p", .member_loads = {ml}});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const BeamStations st = stations(s, sol, 0, 17);  // x = k / 20: a = 0.5 is station 10
  const double EI = kSteel.E * sec.Iz, GAs = kSteel.G * sec.Asy;
  auto v = [&](double x) {
    if (x <= a) return P * x * x * (3 * a - x) / (6 * EI) + P * x / GAs;
    return P * a * a * a / (3 * EI) + P * a / GAs + P * a * a / (2 * EI) * (x - a);
  };
  expect_curve(st, false, 1, v, kRel);
  // The tip node agrees: the nodal solution is exact too.
  EXPECT_NEAR(sol.cases[0].displacement[1](1), v(L), kRel * v(L));
  // Shear P before a and 0 after it (the station at a reports the value just after the load).
  expect_curve(
      st, true, 1, [&](double x) { return x < a ? P : 0.0; }, kRel);
}

TEST(MemberStations, TemperatureBendsAFreeCantileverAndNotAClampedBeam) {
  const Section sec = rectangle_section(0.05, 0.1);
  const double L = 2.0;
  MemberLoad ml;
  ml.beam = 0;
  ml.type = MemberLoadType::kTemperature;
  ml.thermal = {.alpha = 1.2e-5, .hy = 0.05, .hz = 0.1, .dT = 30.0, .dTy = 20.0, .dTz = -15.0};
  Structure c = straight(L, 1, sec);
  c.add_support({0, kAllDofs, Mat3::Identity()});
  c.add_load_case({.name = "heat", .member_loads = {ml}});
  const Solution cs = solve(c);
  ASSERT_TRUE(cs.status.ok()) << cs.status.message();
  const BeamStations st = stations(c, cs, 0, 5);
  const double ky = 1.2e-5 * 20.0 / 0.05, kz = 1.2e-5 * -15.0 / 0.1;
  expect_curve(
      st, false, 0, [&](double x) { return 1.2e-5 * 30.0 * x; }, kRel);
  expect_curve(
      st, false, 1, [&](double x) { return -ky * x * x / 2; }, kRel);
  expect_curve(
      st, false, 2, [&](double x) { return -kz * x * x / 2; }, kRel);
  for (const Vec6& f : st.forces) EXPECT_LT(f.norm(), 1e-6) << "a free beam carries no force";

  Structure b = straight(L, 2, sec);  // clamped at both ends
  b.add_support({0, kAllDofs, Mat3::Identity()});
  b.add_support({2, kAllDofs, Mat3::Identity()});
  MemberLoad ml1 = ml;
  ml1.beam = 1;
  b.add_load_case({.name = "heat", .member_loads = {ml, ml1}});
  const Solution bs = solve(b);
  ASSERT_TRUE(bs.status.ok()) << bs.status.message();
  const BeamStations sb = stations(b, bs, 0, 5);
  for (const Vec6& u : sb.displacement) EXPECT_LT(u.norm(), 1e-15) << "held straight";
  const double N = kSteel.E * sec.A * 1.2e-5 * 30.0;
  expect_curve(
      sb, true, 0, [&](double) { return -N; }, kRel);
}

TEST(MemberStations, ReleasedEndRotatesAwayFromItsNode) {
  // Propped cantilever by a release about z at the beam's second end (node held in translation by
  // support, in rotation by an unloaded second beam): v(x) = -w x^2 (3L^2 - 5Lx + 2x^2) / (48 EI),
  // and the beam's end turns by w L^3 / (48 EI) while the node does not turn.
  const Section sec = rectangle_section(0.04, 0.08);
  const double L = 2.5, w = 1800.0;
  Structure s;
  s.add_material(kSteel);
  s.add_section(sec);
  for (int i = 0; i < 3; ++i) s.add_node(std::to_string(i), Vec3(L * i, 0, 0));
  for (int i = 0; i < 2; ++i) {
    Beam b;
    b.id = fmt::format("b{}", i);
    b.node1 = i;
    b.node2 = i + 1;
    b.material = 0;
    b.section = 0;
    b.releases[11] = i == 0;
    s.add_beam(b);
  }
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_support({1, {true, true, true, false, false, false}, Mat3::Identity()});
  s.add_support({2, kAllDofs, Mat3::Identity()});
  MemberLoad ml;
  ml.beam = 0;
  ml.w1 = Vec3(0, -w, 0);
  s.add_load_case({.name = "udl", .member_loads = {ml}});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const BeamStations st = stations(s, sol, 0, 11);
  const double EI = kSteel.E * sec.Iz;
  expect_curve(
      st, false, 1, [&](double x) { return -w * x * x * (3 * L * L - 5 * L * x + 2 * x * x) / (48 * EI); }, kRel);
  EXPECT_NEAR(st.displacement[10](5), w * L * L * L / (48 * EI), kRel * w * L * L * L / (48 * EI));
  EXPECT_NEAR(sol.cases[0].displacement[1](5), 0.0, 1e-15);
  // Mz = EI v'' = -w (3L^2 - 15Lx + 12x^2) / 24: -w L^2 / 8 at the clamp, 0 at the release.
  expect_curve(
      st, true, 5, [&](double x) { return -w * (3 * L * L - 15 * L * x + 12 * x * x) / 24; }, kRel);
  EXPECT_NEAR(st.forces[10](5), 0.0, kRel * w * L * L);
}

TEST(MemberStations, BadArgumentsAreRefused) {
  Structure s = straight(1.0, 1, circle_section(0.02));
  s.add_support({0, kAllDofs, Mat3::Identity()});
  s.add_load_case({.name = "none"});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok());
  EXPECT_FALSE(beam_stations(s, s.load_cases()[0], sol.cases[0], 3, 5).ok());
  EXPECT_FALSE(beam_stations(s, s.load_cases()[0], sol.cases[0], 0, 1).ok());
}

}  // namespace
}  // namespace kinestat::msa
