// Fixed-end forces of span loads against their textbook closed forms (elements/member_loads.hpp).
// Convention: the force the clamps exert on the beam (k u + FEF are the true end forces), so a load
// along +y gives negative clamp forces along y.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/member_loads.hpp"
#include "kinestat/elements/section.hpp"

namespace kinestat {
namespace {

const Material kSteel{"steel", 2.1e11, 0.81e11};

BeamSpan span(double L, BeamTheory th = BeamTheory::kEulerBernoulli, const Section& s = rectangle_section(0.02, 0.05)) {
  return {kSteel, s, L, th};
}

// Relative tolerance: the closed forms and the quadrature agree to round-off (a few 1e-16 of the
// largest term); 1e-12 of the value leaves a margin of ~1e3.
constexpr double kRel = 1e-12;

TEST(MemberLoads, UniformLoadGivesHalfTheLoadAndWL2Over12) {
  const double L = 2.5, wx = 300.0, wy = -1200.0, wz = 800.0;
  const Vec12 f = uniform_load_fixed_end_forces(span(L), Vec3(wx, wy, wz));
  // x-y plane: R = wL/2, M = wL^2/12 (any fixed-end moment table, e.g. Roark, Table 8.1).
  EXPECT_NEAR(f(1), -wy * L / 2, kRel * std::abs(wy * L));
  EXPECT_NEAR(f(7), -wy * L / 2, kRel * std::abs(wy * L));
  EXPECT_NEAR(f(5), -wy * L * L / 12, kRel * std::abs(wy * L * L));
  EXPECT_NEAR(f(11), wy * L * L / 12, kRel * std::abs(wy * L * L));
  // x-z plane: the same with ry = -dw/dx, so the moment signs flip.
  EXPECT_NEAR(f(2), -wz * L / 2, kRel * std::abs(wz * L));
  EXPECT_NEAR(f(8), -wz * L / 2, kRel * std::abs(wz * L));
  EXPECT_NEAR(f(4), wz * L * L / 12, kRel * std::abs(wz * L * L));
  EXPECT_NEAR(f(10), -wz * L * L / 12, kRel * std::abs(wz * L * L));
  // Axial: half to each clamp; no torsion.
  EXPECT_NEAR(f(0), -wx * L / 2, kRel * std::abs(wx * L));
  EXPECT_NEAR(f(6), -wx * L / 2, kRel * std::abs(wx * L));
  EXPECT_EQ(f(3), 0.0);
  EXPECT_EQ(f(9), 0.0);
}

TEST(MemberLoads, PointForceAndMomentMatchTheFixedEndTables) {
  const double L = 3.0, a = 0.9, b = L - a, P = 5000.0, C = 700.0;
  const Vec12 f = point_load_fixed_end_forces(span(L), a, Vec3(0, P, 0), Vec3::Zero());
  // R1 = P b^2 (3a + b) / L^3, M1 = P a b^2 / L^2, R2 = P a^2 (a + 3b) / L^3, M2 = P a^2 b / L^2.
  EXPECT_NEAR(f(1), -P * b * b * (3 * a + b) / (L * L * L), kRel * P);
  EXPECT_NEAR(f(7), -P * a * a * (a + 3 * b) / (L * L * L), kRel * P);
  EXPECT_NEAR(f(5), -P * a * b * b / (L * L), kRel * P * L);
  EXPECT_NEAR(f(11), P * a * a * b / (L * L), kRel * P * L);
  // The same force along z: equal shears, moments of the opposite sign (ry = -dw/dx).
  const Vec12 fz = point_load_fixed_end_forces(span(L), a, Vec3(0, 0, P), Vec3::Zero());
  EXPECT_NEAR(fz(2), f(1), kRel * P);
  EXPECT_NEAR(fz(4), -f(5), kRel * P * L);
  EXPECT_NEAR(fz(10), -f(11), kRel * P * L);
  // Axial force and torque split by the lever rule: b/L to the first clamp.
  const Vec12 fx = point_load_fixed_end_forces(span(L), a, Vec3(P, 0, 0), Vec3(C, 0, 0));
  EXPECT_NEAR(fx(0), -P * b / L, kRel * P);
  EXPECT_NEAR(fx(6), -P * a / L, kRel * P);
  EXPECT_NEAR(fx(3), -C * b / L, kRel * C);
  EXPECT_NEAR(fx(9), -C * a / L, kRel * C);
  // A moment C about z at a (Roark, Table 8.1): M1 = C b (2a - b) / L^2,
  // M2 = C a (2b - a) / L^2, shears 6 C a b / L^3 forming a couple against C.
  const Vec12 fm = point_load_fixed_end_forces(span(L), a, Vec3::Zero(), Vec3(0, 0, C));
  EXPECT_NEAR(fm(5), C * b * (2 * a - b) / (L * L), kRel * C);
  EXPECT_NEAR(fm(11), C * a * (2 * b - a) / (L * L), kRel * C);
  EXPECT_NEAR(fm(1), 6 * C * a * b / (L * L * L), kRel * C / L);
  EXPECT_NEAR(fm(7), -6 * C * a * b / (L * L * L), kRel * C / L);
  // About y the same with the roles of the signs of z and ry exchanged.
  const Vec12 fmy = point_load_fixed_end_forces(span(L), a, Vec3::Zero(), Vec3(0, C, 0));
  EXPECT_NEAR(fmy(4), fm(5), kRel * C);
  EXPECT_NEAR(fmy(10), fm(11), kRel * C);
  EXPECT_NEAR(fmy(2), -fm(1), kRel * C / L);
}

// Simpson's rule on n (even) intervals.
double simpson(const std::function<double(double)>& g, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = g(a) + g(b);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * g(a + i * h);
  return s * h / 3.0;
}

TEST(MemberLoads, TrapezoidalLoadMatchesTheIntegratedGreensFunctionAndTheTriangleTable) {
  const double L = 4.0, a = 0.7, b = 3.1, w1 = 1000.0, w2 = -400.0;
  const Vec12 f = trapezoidal_load_fixed_end_forces(span(L), a, b, Vec3(0, w1, 0), Vec3(0, w2, 0));
  // The point-load table integrated against w(x) dx (the fixed-fixed beam's Green's function),
  // by Simpson's rule on 2000 intervals: error ~ h^4 f'''' ~ 1e-12 of the result.
  auto w = [&](double x) { return w1 + (w2 - w1) * (x - a) / (b - a); };
  auto R1 = [&](double x) {
    const double c = L - x;
    return w(x) * c * c * (3 * x + c) / (L * L * L);
  };
  auto M1 = [&](double x) {
    const double c = L - x;
    return w(x) * x * c * c / (L * L);
  };
  auto R2 = [&](double x) {
    const double c = L - x;
    return w(x) * x * x * (x + 3 * c) / (L * L * L);
  };
  auto M2 = [&](double x) {
    const double c = L - x;
    return w(x) * x * x * c / (L * L);
  };
  const double scale = std::abs(w1) * L;
  EXPECT_NEAR(f(1), -simpson(R1, a, b, 2000), 1e-10 * scale);
  EXPECT_NEAR(f(5), -simpson(M1, a, b, 2000), 1e-10 * scale * L);
  EXPECT_NEAR(f(7), -simpson(R2, a, b, 2000), 1e-10 * scale);
  EXPECT_NEAR(f(11), simpson(M2, a, b, 2000), 1e-10 * scale * L);

  // Full span: uniform w1 plus a triangle rising from 0 to (w2 - w1), whose table values are
  // R1 = 3wL/20, R2 = 7wL/20, M1 = wL^2/30, M2 = wL^2/20 (w at the second end).
  const Vec12 g = trapezoidal_load_fixed_end_forces(span(L), 0.0, L, Vec3(0, 0, w1), Vec3(0, 0, w2));
  const double t = w2 - w1;
  EXPECT_NEAR(g(2), -(w1 * L / 2 + 3 * t * L / 20), kRel * scale);
  EXPECT_NEAR(g(8), -(w1 * L / 2 + 7 * t * L / 20), kRel * scale);
  EXPECT_NEAR(g(4), w1 * L * L / 12 + t * L * L / 30, kRel * scale * L);
  EXPECT_NEAR(g(10), -(w1 * L * L / 12 + t * L * L / 20), kRel * scale * L);
}

TEST(MemberLoads, TimoshenkoUniformLoadKeepsTheMomentsPointLoadDoesNot) {
  // A stocky beam: Phi = 12 E I / (G As L^2) = 0.50 about z, 1.1 about y.
  const Section s = rectangle_section(0.2, 0.3);
  const double L = 0.5, w = -2000.0;
  const BeamSpan tim = span(L, BeamTheory::kTimoshenko, s);
  const double phi_y = 12 * kSteel.E * s.Iz / (kSteel.G * s.Asy * L * L);
  ASSERT_NEAR(phi_y, 0.498, 0.001);
  // Uniform load: symmetric, so the end slopes vanish whatever the shear flexibility and the
  // fixed-end moments stay wL^2/12 (the compatibility condition is the integral of M/EI, shear
  // deformation adds only a rigid offset).
  const Vec12 u = uniform_load_fixed_end_forces(tim, Vec3(0, w, w));
  EXPECT_NEAR(u(5), -w * L * L / 12, kRel * std::abs(w) * L * L);
  EXPECT_NEAR(u(4), w * L * L / 12, kRel * std::abs(w) * L * L);
  EXPECT_NEAR(u(1), -w * L / 2, kRel * std::abs(w) * L);

  // Point load P at a: derived here by the force method, independently of the shape functions.
  // Free the first end: the cantilever clamped at x = L deflects at x = a by
  // v(a) = P b^3/(3EI) + P b/(G As) with rotation theta(a) = -P b^2/(2EI); the unloaded stretch
  // [0, a] carries no shear, so it stays straight: v(0) = v(a) - theta(a) a, theta(0) = theta(a).
  // The first clamp must bring that end back: its forces are -K11 (v(0), theta(0)), with K11 the
  // end-1 block of the (tested) Timoshenko stiffness. Closed form of the result:
  // M1 = P [a b^2/L^2 + Phi a b/(2L)] / (1 + Phi), R1 = P [b^2 (3a + b)/L^3 + Phi b/L] / (1 + Phi).
  const double a = 0.15, b = L - a, P = 9000.0, EI = kSteel.E * s.Iz, GAs = kSteel.G * s.Asy;
  const Vec12 p = point_load_fixed_end_forces(tim, a, Vec3(0, P, 0), Vec3::Zero());
  const Mat12 K = beam_local_stiffness(kSteel, s, L, BeamTheory::kTimoshenko);
  const double th = -P * b * b / (2 * EI), v = P * b * b * b / (3 * EI) + P * b / GAs - th * a;
  Eigen::Vector2d d(v, th);
  Eigen::Matrix2d K11;
  K11 << K(1, 1), K(1, 5), K(5, 1), K(5, 5);
  const Eigen::Vector2d clamp = -K11 * d;
  EXPECT_NEAR(p(1), clamp(0), kRel * P);
  EXPECT_NEAR(p(5), clamp(1), kRel * P * L);
  EXPECT_NEAR(p(5), -P * (a * b * b / (L * L) + phi_y * a * b / (2 * L)) / (1 + phi_y), kRel * P * L);
  EXPECT_NEAR(p(1), -P * (b * b * (3 * a + b) / (L * L * L) + phi_y * b / L) / (1 + phi_y), kRel * P);
  // ... and it differs from Euler-Bernoulli by far more than the tolerance (Phi ~ 0.5).
  const Vec12 eb = point_load_fixed_end_forces(span(L, BeamTheory::kEulerBernoulli, s), a, Vec3(0, P, 0), Vec3::Zero());
  EXPECT_GT(std::abs(p(5) - eb(5)), 0.05 * std::abs(eb(5)));
  // Equilibrium of the clamped beam: the clamps' forces balance P and its moment about the first end.
  EXPECT_NEAR(p(1) + p(7), -P, kRel * P);
  EXPECT_NEAR(p(5) + p(11) + p(7) * L, -P * a, kRel * P * L);

  // The x-z plane, with its own sign convention (uz, ry = -dw/dx), by the same construction.
  const double EIy = kSteel.E * s.Iy, GAz = kSteel.G * s.Asz;
  const Vec12 q = point_load_fixed_end_forces(tim, a, Vec3(0, 0, P), Vec3::Zero());
  const double thz = -P * b * b / (2 * EIy), wz = P * b * b * b / (3 * EIy) + P * b / GAz - thz * a;
  Eigen::Matrix2d K11z;
  K11z << K(2, 2), K(2, 4), K(4, 2), K(4, 4);
  const Eigen::Vector2d clampz = -K11z * Eigen::Vector2d(wz, -thz);
  EXPECT_NEAR(q(2), clampz(0), kRel * P);
  EXPECT_NEAR(q(4), clampz(1), kRel * P * L);
}

TEST(MemberLoads, ProppedBeamUnderUniformLoadByCondensation) {
  // Clamped at the first end, pinned about z at the second: R1 = 5wL/8, M1 = wL^2/8, R2 = 3wL/8.
  const double L = 2.0, w = 1500.0;
  const BeamSpan sp = span(L);
  BeamReleases rel{};
  rel[11] = true;
  const Mat12 K = beam_local_stiffness(sp.material, sp.section, L, sp.theory);
  auto f = condense_fixed_end_forces(K, rel, uniform_load_fixed_end_forces(sp, Vec3(0, w, 0)));
  ASSERT_TRUE(f.ok()) << f.status().message();
  EXPECT_NEAR((*f)(1), -5 * w * L / 8, kRel * w * L);
  EXPECT_NEAR((*f)(5), -w * L * L / 8, kRel * w * L * L);
  EXPECT_NEAR((*f)(7), -3 * w * L / 8, kRel * w * L);
  EXPECT_EQ((*f)(11), 0.0);
  // Released at both ends about x: the condensation refuses, as condense_releases does.
  BeamReleases spin{};
  spin[3] = spin[9] = true;
  EXPECT_FALSE(condense_fixed_end_forces(K, spin, Vec12::Zero()).ok());
}

TEST(MemberLoads, TemperatureClampsTheFreeStrainAndCurvature) {
  const Section s = rectangle_section(0.05, 0.1);
  const BeamSpan sp = span(3.0, BeamTheory::kTimoshenko, s);
  const ThermalLoad t{.alpha = 1.2e-5, .hy = 0.05, .hz = 0.1, .dT = 40.0, .dTy = 10.0, .dTz = -25.0};
  const Vec12 f = temperature_fixed_end_forces(sp, t);
  const double N = kSteel.E * s.A * t.alpha * t.dT;
  // Compression -E A alpha dT: the clamps push the ends inwards.
  EXPECT_NEAR(f(6), -N, kRel * N);
  EXPECT_NEAR(f(0), N, kRel * N);
  const double Mz = kSteel.E * s.Iz * t.alpha * t.dTy / t.hy, My = kSteel.E * s.Iy * t.alpha * t.dTz / t.hz;
  EXPECT_NEAR(f(11), Mz, kRel * std::abs(Mz));
  EXPECT_NEAR(f(5), -Mz, kRel * std::abs(Mz));
  EXPECT_NEAR(f(10), -My, kRel * std::abs(My));
  EXPECT_NEAR(f(4), My, kRel * std::abs(My));
  for (int i : {1, 2, 3, 7, 8, 9}) EXPECT_EQ(f(i), 0.0) << i;
}

}  // namespace
}  // namespace kinestat
