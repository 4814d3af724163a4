// Member loads and self-weight in the static solve: closed-form beams, true end forces (k T u + FEF),
// reactions and the equilibrium of the equivalent nodal loads.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "beam_line.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "msa/assembly.hpp"

namespace kinestat::msa {
namespace {

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

MemberLoad uniform(int beam, const Vec3& w, bool global = true) {
  MemberLoad ml;
  ml.beam = beam;
  ml.type = MemberLoadType::kUniform;
  ml.global_axes = global;
  ml.w1 = w;
  return ml;
}

// Nodal displacements of elements with exact fixed-end forces are exact, so the comparisons with the
// closed forms are at round-off: measured up to 5e-15 of the value here (the three-element
// cantilever), so 1e-12 leaves a margin of 200 for other compilers and BLAS.
constexpr double kRel = 1e-12;

TEST(MemberLoadSolve, SimplySupportedBeamUnderUniformLoad) {
  const Section sec = rectangle_section(0.04, 0.08);
  const double L = 3.0, q = 2500.0;  // load -q along global z
  Structure s = straight(L, 2, sec);
  s.add_support({0, {true, true, true, true, false, false}, Mat3::Identity()});
  s.add_support({2, {false, true, true, false, false, false}, Mat3::Identity()});
  LoadCase lc{.name = "udl"};
  for (int b = 0; b < 2; ++b) lc.member_loads.push_back(uniform(b, Vec3(0, 0, -q)));
  s.add_load_case(lc);
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const LoadCaseResult& r = sol.cases[0];
  const double EI = kSteel.E * sec.Iy;
  const double mid = 5 * q * L * L * L * L / (384 * EI);
  EXPECT_NEAR(r.displacement[1](2), -mid, kRel * mid);
  EXPECT_NEAR(r.displacement[1](4), 0.0, kRel * mid / L);  // symmetric: no slope at midspan
  // End slopes q L^3 / (24 EI).
  EXPECT_NEAR(r.displacement[0](4), q * L * L * L / (24 * EI), kRel * mid / L);
  // Reactions q L / 2 at each support, equilibrium exact.
  EXPECT_NEAR(r.reaction[0](2), q * L / 2, kRel * q * L);
  EXPECT_NEAR(r.reaction[2](2), q * L / 2, kRel * q * L);
  EXPECT_LT(r.equilibrium_error, 1e-14);
  // True end forces: no moment at the supports, q L^2 / 8 at midspan (sagging: My = -EI w'' < 0 on
  // the +x face), no shear at midspan, q L / 2 at the supports.
  const double M = q * L * L / 8;
  EXPECT_NEAR(r.beam_end_forces[0](4), 0.0, kRel * M);
  EXPECT_NEAR(r.beam_end_forces[1](10), 0.0, kRel * M);
  EXPECT_NEAR(r.beam_end_forces[0](10), -M, kRel * M);
  EXPECT_NEAR(r.beam_end_forces[1](4), M, kRel * M);
  EXPECT_NEAR(r.beam_end_forces[0](8), 0.0, kRel * q * L);
  EXPECT_NEAR(r.beam_end_forces[0](2), q * L / 2, kRel * q * L);
}

TEST(MemberLoadSolve, CantileverUnderSelfWeight) {
  const Section sec = circle_section(0.05);
  const double L = 2.0, g = 9.81;
  for (int n : {1, 3}) {
    Structure s = straight(L, n, sec);
    s.add_support({0, kAllDofs, Mat3::Identity()});
    s.add_load_case({.name = "weight", .gravity = Vec3(0, 0, -g)});
    const Solution sol = solve(s);
    ASSERT_TRUE(sol.status.ok()) << sol.status.message();
    const LoadCaseResult& r = sol.cases[0];
    const double q = kSteel.density * sec.A * g, EI = kSteel.E * sec.Iy;
    const double tip = q * L * L * L * L / (8 * EI);
    EXPECT_NEAR(r.displacement[n](2), -tip, kRel * tip) << n;
    // The root: reaction q L up and moment -q L^2 / 2 about y (the weight's moment is +q L^2/2).
    const double M = q * L * L / 2;
    EXPECT_NEAR(r.reaction[0](2), q * L, kRel * q * L) << n;
    EXPECT_NEAR(r.reaction[0](4), -M, kRel * M) << n;
    // The first beam's end force at the root is the reaction (local axes = global for a beam on x).
    EXPECT_NEAR(r.beam_end_forces[0](2), q * L, kRel * q * L) << n;
    EXPECT_NEAR(r.beam_end_forces[0](4), -M, kRel * M) << n;
    // The free end carries nothing: without the fixed-end forces it would show q L/(2n) and q L^2/(12 n^2).
    EXPECT_NEAR(r.beam_end_forces[n - 1](8), 0.0, kRel * q * L) << n;
    EXPECT_NEAR(r.beam_end_forces[n - 1](10), 0.0, kRel * M) << n;
    EXPECT_LT(r.equilibrium_error, 1e-14) << n;
  }
}

TEST(MemberLoadSolve, TemperatureInAClampedBeamAndAFreeCantilever) {
  const Section sec = rectangle_section(0.05, 0.1);
  const double L = 2.0;
  const ThermalLoad t{.alpha = 1.2e-5, .hy = 0.05, .hz = 0.1, .dT = 30.0, .dTy = 20.0, .dTz = -15.0};
  MemberLoad ml;
  ml.beam = 0;
  ml.type = MemberLoadType::kTemperature;
  ml.thermal = t;
  for (BeamTheory th : {BeamTheory::kEulerBernoulli, BeamTheory::kTimoshenko}) {
    // Clamped at both ends, heated along its two halves: nothing moves, the end forces are the
    // fixed-end forces.
    Structure s = straight(L, 2, sec, th);
    s.add_support({0, kAllDofs, Mat3::Identity()});
    s.add_support({2, kAllDofs, Mat3::Identity()});
    MemberLoad ml1 = ml;
    ml1.beam = 1;
    s.add_load_case({.name = "heat", .member_loads = {ml, ml1}});
    const Solution sol = solve(s);
    ASSERT_TRUE(sol.status.ok()) << sol.status.message();
    const LoadCaseResult& r = sol.cases[0];
    const double N = kSteel.E * sec.A * t.alpha * t.dT;
    EXPECT_NEAR(r.beam_end_forces[0](6), -N, kRel * N);  // axial force -E A alpha dT: compression
    EXPECT_NEAR(r.reaction[0](0), N, kRel * N);          // the left wall pushes along +x
    EXPECT_NEAR(r.reaction[2](0), -N, kRel * N);
    const double Mz = kSteel.E * sec.Iz * t.alpha * t.dTy / t.hy;
    const double My = kSteel.E * sec.Iy * t.alpha * t.dTz / t.hz;
    EXPECT_NEAR(r.beam_end_forces[0](11), Mz, kRel * Mz);
    EXPECT_NEAR(r.beam_end_forces[0](10), -My, kRel * std::abs(My));
    EXPECT_NEAR(r.beam_end_forces[1](11), Mz, kRel * Mz);
    EXPECT_LT(r.displacement[1].norm(), 1e-15 * t.alpha * t.dT * L);

    // Clamped at one end only: the beam takes its free thermal shape and carries no force, which
    // ties the signs of the fixed-end forces to those of the stiffness.
    Structure c = straight(L, 1, sec, th);
    c.add_support({0, kAllDofs, Mat3::Identity()});
    c.add_load_case({.name = "heat", .member_loads = {ml}});
    const Solution cs = solve(c);
    ASSERT_TRUE(cs.status.ok()) << cs.status.message();
    const Vec6 tip = cs.cases[0].displacement[1];
    const double ky = t.alpha * t.dTy / t.hy, kz = t.alpha * t.dTz / t.hz;  // a hot +y face bends it to -y
    EXPECT_NEAR(tip(0), t.alpha * t.dT * L, kRel * t.alpha * t.dT * L);
    EXPECT_NEAR(tip(5), -ky * L, kRel * ky * L);
    EXPECT_NEAR(tip(1), -ky * L * L / 2, kRel * ky * L * L);
    EXPECT_NEAR(tip(2), -kz * L * L / 2, kRel * std::abs(kz) * L * L);
    EXPECT_NEAR(tip(4), kz * L, kRel * std::abs(kz) * L);  // ry = -dw/dx
    EXPECT_LT(cs.cases[0].beam_end_forces[0].norm(), kRel * N);
    EXPECT_LT(cs.cases[0].reaction[0].norm(), kRel * N);
  }
}

TEST(MemberLoadSolve, ProppedCantileverThroughAnEndRelease) {
  // Beam b0 clamped at node 0 and released about z at node 1 (which is held in translation): a
  // propped cantilever. The unloaded b1 (node 1 to the clamped node 2) only gives node 1's rz a
  // stiffness; it carries nothing since the release passes no moment.
  const Section sec = rectangle_section(0.04, 0.08);
  const double L = 2.5, w = 1800.0;
  Structure s;
  s.add_material(kSteel);
  s.add_section(sec);
  s.add_node("0", Vec3::Zero());
  s.add_node("1", Vec3(L, 0, 0));
  s.add_node("2", Vec3(2 * L, 0, 0));
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
  s.add_load_case({.name = "udl", .member_loads = {uniform(0, Vec3(0, -w, 0))}});
  const Solution sol = solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  const LoadCaseResult& r = sol.cases[0];
  // R = 5wL/8 and M = wL^2/8 at the clamp, 3wL/8 at the prop (Roark, Table 8.1).
  EXPECT_NEAR(r.reaction[0](1), 5 * w * L / 8, kRel * w * L);
  EXPECT_NEAR(r.reaction[0](5), w * L * L / 8, kRel * w * L * L);
  EXPECT_NEAR(r.reaction[1](1), 3 * w * L / 8, kRel * w * L);
  EXPECT_NEAR(r.beam_end_forces[0](5), w * L * L / 8, kRel * w * L * L);
  EXPECT_NEAR(r.beam_end_forces[0](11), 0.0, kRel * w * L * L);
  EXPECT_LT(r.beam_end_forces[1].norm(), kRel * w * L);
  EXPECT_LT(r.equilibrium_error, 1e-14);
}

TEST(MemberLoadSolve, EquivalentNodalLoadsHaveTheResultantOfTheSpanLoads) {
  // An oblique beam with every kind of mechanical span load, local and global: the equivalent nodal
  // loads -T' FEF must have the span loads' force and moment about the origin.
  Structure s;
  s.add_material(kSteel);
  s.add_section(rectangle_section(0.03, 0.07));
  const Vec3 p1(0.2, -0.5, 0.3), p2(1.9, 0.8, 1.4);
  s.add_node("A", p1);
  s.add_node("B", p2);
  Beam b;
  b.id = "b";
  b.node1 = 0;
  b.node2 = 1;
  b.material = 0;
  b.section = 0;
  b.orientation = Vec3(0.3, 1.0, -0.2);
  b.theory = BeamTheory::kTimoshenko;
  s.add_beam(b);
  const double L = (p2 - p1).norm();
  const Mat3 R = s.beam_axes(s.beams()[0]);
  const Vec3 ex = R.col(0);
  MemberLoad trap;
  trap.beam = 0;
  trap.type = MemberLoadType::kTrapezoidal;
  trap.a = 0.2 * L;
  trap.b = 0.9 * L;
  trap.w1 = Vec3(100, -300, 250);
  trap.w2 = Vec3(-50, 400, 80);  // local
  MemberLoad pt;
  pt.beam = 0;
  pt.type = MemberLoadType::kPoint;
  pt.global_axes = true;
  pt.a = 0.35 * L;
  pt.force = Vec3(500, -200, 900);
  pt.moment = Vec3(30, 40, -60);
  LoadCase lc{.name = "mix", .gravity = Vec3(1.0, -2.0, -9.81), .member_loads = {trap, pt, uniform(0, Vec3(7, 8, -9))}};
  auto fef = fixed_end_forces(s, lc);
  ASSERT_TRUE(fef.ok()) << fef.status().message();
  const VecX f = equivalent_nodal_loads(s, *fef);
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  for (int n = 0; n < 2; ++n) {
    force += f.segment<3>(6 * n);
    moment += f.segment<3>(6 * n + 3) + s.nodes()[n].position.cross(f.segment<3>(6 * n));
  }
  // Span loads, integrated by hand: a trapezoid's resultant (w1 + w2)/2 (b - a) acts at its centroid
  // a + (b - a)(w1 + 2 w2) / (3 (w1 + w2)) along x, per component.
  Vec3 F = Vec3::Zero(), Mo = Vec3::Zero();
  auto add = [&](const Vec3& force_global, double x) {
    F += force_global;
    Mo += (p1 + x * ex).cross(force_global);
  };
  for (int k = 0; k < 3; ++k) {
    const double w1 = trap.w1(k), w2 = trap.w2(k), len = trap.b - trap.a;
    // As two pieces (uniform w1 at mid, triangle w2 - w1 at two thirds) so that w1 + w2 = 0 is fine.
    add(R.col(k) * (w1 * len), trap.a + len / 2);
    add(R.col(k) * ((w2 - w1) * len / 2), trap.a + 2 * len / 3);
  }
  add(pt.force, pt.a);
  Mo += pt.moment;
  add(Vec3(7, 8, -9) * L, L / 2);
  add(kSteel.density * s.sections()[0].A * lc.gravity * L, L / 2);
  EXPECT_LT((force - F).norm(), 1e-12 * F.norm());
  EXPECT_LT((moment - Mo).norm(), 1e-12 * (Mo.norm() + F.norm() * L));
}

TEST(MemberLoadSolve, ValidationNamesTheItemAndTheFix) {
  Structure s = straight(2.0, 1, circle_section(0.02));
  s.add_support({0, kAllDofs, Mat3::Identity()});
  auto message = [&](MemberLoad ml) {
    Structure t = s;
    ml.source = "frame.yaml:21";
    t.add_load_case({.name = "c", .member_loads = {ml}});
    return t.validate().message();
  };
  MemberLoad missing = uniform(3, Vec3(0, 0, -1));
  expect_contains(message(missing),
                  "frame.yaml:21: load case 'c': a member load is applied to a beam that does not exist");
  MemberLoad outside;
  outside.beam = 0;
  outside.type = MemberLoadType::kPoint;
  outside.a = 2.5;
  outside.force = Vec3(0, 0, 1);
  expect_contains(message(outside),
                  "frame.yaml:21: load case 'c': the member load on beam 'b0': a = 2.5 m lies outside "
                  "the beam (length 2 m)");
  MemberLoad reversed = outside;
  reversed.type = MemberLoadType::kTrapezoidal;
  reversed.a = 1.5;
  reversed.b = 0.5;
  expect_contains(message(reversed), "give a < b");
  MemberLoad heat;
  heat.beam = 0;
  heat.type = MemberLoadType::kTemperature;
  heat.thermal = {.alpha = 1e-5, .dTy = 10.0};  // a gradient without its depth
  expect_contains(message(heat), "hy = 0 m must be positive");
  Structure dense = s;
  Material m = kSteel;
  m.id = "lead";
  m.density = -11340.0;
  dense.add_material(m);
  expect_contains(dense.validate().message(), "material 'lead': density = -11340 kg/m^3 must not be negative");
  Structure g = s;
  g.add_load_case({.name = "g", .source = "frame.yaml:30", .gravity = Vec3(0, 0, NAN)});
  expect_contains(g.validate().message(), "frame.yaml:30: load case 'g': gravity z = nan m/s^2 is not a finite number");
  // Gravity on weightless materials would silently load nothing.
  Material weightless = kSteel;
  weightless.density = 0.0;
  Structure only_light = straight(2.0, 1, circle_section(0.02), BeamTheory::kEulerBernoulli, weightless);
  only_light.add_load_case({.name = "g", .source = "frame.yaml:31", .gravity = Vec3(0, 0, -9.81)});
  expect_contains(only_light.validate().message(),
                  "frame.yaml:31: load case 'g': gravity is given but no beam's material has a density");
}

}  // namespace
}  // namespace kinestat::msa
