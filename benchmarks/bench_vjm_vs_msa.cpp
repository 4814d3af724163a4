// The 5R five-bar of Gonçalves et al. 2010 (section 5) by two methods on the same inputs: MSA
// (mechanisms::make_five_bar_structure, Cartesian stiffness of the platform node by static
// condensation) and the VJM (two serial chains meeting at P: locked actuator, beam springs = the
// cantilever condensation of each beam, passive revolutes with the joints' springs in the other five
// dofs). For beams and linear springs both models are exact, so the 6x6 matrices agree to round-off
// (~1e-8 here: the 2e11 joint springs next to ~1e4 N/m of link stiffness cost ~7 of the 16 digits).
// The counter `max_rel_diff` reports max|K_vjm - K_msa| / max|K_msa|; the time is per posture
// (model built and solved from the posture). The Orthoglide is not built as an MSA frame here.
// Run: ./build/benchmarks/bench_vjm_vs_msa   (figures: benchmarks/README.md)
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "mechanisms/five_bar.hpp"
#include "msa/static_analysis.hpp"
#include "vjm/link_spring.hpp"
#include "vjm/stiffness.hpp"

namespace kinestat {
namespace {

using mechanisms::FiveBarParams;
using mechanisms::FiveBarPosture;
using mechanisms::Vec2;

constexpr double kDeg = std::numbers::pi / 180.0;

// Postures of the paper's Table 1 region (theta1, theta2 in deg, up assembly): row 14 and two others.
const std::array<std::array<double, 2>, 3> kPostures = {{{64.0, 75.0}, {60.0, 80.0}, {70.0, 100.0}}};

FiveBarPosture posture(const FiveBarParams& p, int i) {
  return *mechanisms::direct_kinematics(p, kPostures[static_cast<std::size_t>(i)][0] * kDeg,
                                        kPostures[static_cast<std::size_t>(i)][1] * kDeg, mechanisms::Assembly::kUp);
}

double direction(const Vec2& from, const Vec2& to) { return std::atan2(to.y() - from.y(), to.x() - from.x()); }

// The revolute joint of the MSA model (joint_stiffness, global axes, kr_z = 0) as a VJM spring plus a
// passive rotation about z: the passive joint makes the spring's rz entry irrelevant, so it is set to
// kr_x to keep the spring positive definite.
Mat6 joint_spring(const FiveBarParams& p) {
  Vec6 k = p.joint_stiffness;
  k(5) = k(3);
  return k.asDiagonal();
}

// A chain from the fixed motor at A through links `points` (A, B, [P side...]) to P, in global axes at P.
// Every frame has z = global z, so the joints' springs (isotropic in x-y) need no rotation.
vjm::Chain five_bar_chain(const FiveBarParams& p, const std::vector<Vec2>& points, bool joint_at_end,
                          const char* name) {
  vjm::Chain c(name);
  vjm::Transform base = vjm::Transform::Identity();
  base.translation() = Vec3(points[0].x(), points[0].y(), 0.0);
  c.add_transform(base, "motor");
  double angle = direction(points[0], points[1]);
  c.add_actuator(vjm::JointType::kRevolute, Vec3::UnitZ(), angle, std::numeric_limits<double>::infinity(),
                 "locked actuator");
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double length = (points[i] - points[i - 1]).norm();
    c.add_translation(length * Vec3::UnitX(), "link");
    c.add_spring(vjm::cantilever_spring(p.link_material, p.link_section, length, BeamTheory::kEulerBernoulli), "link");
    if (i + 1 < points.size() || joint_at_end) {
      const double next = i + 1 < points.size() ? direction(points[i], points[i + 1]) : angle;
      c.add_spring(joint_spring(p), "joint");
      c.add_passive(vjm::JointType::kRevolute, Vec3::UnitZ(), next - angle, "joint");
      angle = next;
    }
  }
  c.add_rotation(Vec3::UnitZ(), -angle, "tool (global axes)");
  return c;
}

Mat6 vjm_stiffness(const FiveBarParams& p, const FiveBarPosture& q) {
  // The MSA report node "5" (index 4) is P on the PB2 link: chain 1 crosses the P joint, chain 2 ends there.
  const std::vector<vjm::Chain> chains = {five_bar_chain(p, {q.A1, q.B1, q.P}, true, "left leg"),
                                          five_bar_chain(p, {q.A2, q.B2, q.P}, false, "right leg")};
  return vjm::platform_unloaded_stiffness(chains)->stiffness;
}

Mat6 msa_stiffness(const FiveBarParams& p, const FiveBarPosture& q, msa::Workspace& ws) {
  const msa::Structure s = mechanisms::make_five_bar_structure(p, q);
  return msa::cartesian_stiffness(s, ws, mechanisms::kFiveBarPlatformNode)->stiffness;
}

double max_rel_diff(int i) {
  const FiveBarParams p;
  msa::Workspace ws;
  const Mat6 Km = msa_stiffness(p, posture(p, i), ws);
  return (vjm_stiffness(p, posture(p, i)) - Km).cwiseAbs().maxCoeff() / Km.cwiseAbs().maxCoeff();
}

void BM_FiveBarVjm(benchmark::State& state) {
  const FiveBarParams p;
  const FiveBarPosture q = posture(p, static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(vjm_stiffness(p, q));
  state.counters["max_rel_diff"] = max_rel_diff(static_cast<int>(state.range(0)));
}

void BM_FiveBarMsa(benchmark::State& state) {
  const FiveBarParams p;
  const FiveBarPosture q = posture(p, static_cast<int>(state.range(0)));
  msa::Workspace ws;  // symbolic analysis reused across postures, as in a sweep
  for (auto _ : state) benchmark::DoNotOptimize(msa_stiffness(p, q, ws));
  state.counters["max_rel_diff"] = max_rel_diff(static_cast<int>(state.range(0)));
}

BENCHMARK(BM_FiveBarVjm)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FiveBarMsa)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace kinestat

BENCHMARK_MAIN();
