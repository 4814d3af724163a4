// The 5R five-bar of Gonçalves et al. 2010 (section 5) by two methods on the same inputs: MSA
// (mechanisms::make_five_bar_structure, Cartesian stiffness of the platform node by static
// condensation) and the VJM (two serial chains meeting at P: locked actuator, beam springs = the
// cantilever condensation of each beam, passive revolutes with the joints' springs in the other five
// dofs). For beams and linear springs both models are exact, so the 6x6 matrices agree to round-off
// (~1e-8 here: the 2e11 joint springs next to ~1e4 N/m of link stiffness cost ~7 of the 16 digits).
// The counter `max_rel_diff` reports max|K_vjm - K_msa| / max|K_msa|; the time is per posture
// (model built and solved from the posture).
// The Orthoglide 3-PUU and 3-PRPaR (Pashkevich et al. 2009, default OrthoglideStiffnessModel) at Q0 and
// the tables' Q1: the VJM chains of mechanisms::orthoglide_chains (platform_unloaded_stiffness) against
// the same mechanism as an MSA frame, mechanisms::orthoglide_frame (beams, joints with released
// rotations, rigid plates; 16 / 40 nodes), solved with a reused msa::Workspace. Both are exact for
// these elements: max_rel_diff ~1e-14 to 1e-12 (tests/mechanisms/orthoglide_frame_test.cpp).
// Run: ./build/benchmarks/bench_vjm_vs_msa   (figures: benchmarks/README.md)
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <vector>

#include "kinestat/core/units.hpp"
#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/mechanisms/five_bar_vjm.hpp"
#include "kinestat/mechanisms/orthoglide_frame.hpp"
#include "kinestat/mechanisms/orthoglide_stiffness.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat {
namespace {

using mechanisms::FiveBarParams;
using mechanisms::FiveBarPosture;

using units::kDeg;

// Postures of the paper's Table 1 region (theta1, theta2 in deg, up assembly): row 14 and two others.
const std::array<std::array<double, 2>, 3> kPostures = {{{64.0, 75.0}, {60.0, 80.0}, {70.0, 100.0}}};

FiveBarPosture posture(const FiveBarParams& p, int i) {
  return *mechanisms::direct_kinematics(p, kPostures[static_cast<std::size_t>(i)][0] * kDeg,
                                        kPostures[static_cast<std::size_t>(i)][1] * kDeg, mechanisms::Assembly::kUp);
}

Mat6 vjm_stiffness(const FiveBarParams& p, const FiveBarPosture& q) {
  return vjm::platform_unloaded_stiffness(mechanisms::five_bar_vjm_chains(p, q))->stiffness;
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

// Orthoglide cases, benchmark argument 0..3: architecture x posture (tables' x = y = z in mm).
struct OrthoglideCase {
  mechanisms::OrthoglideArchitecture architecture;
  double table_mm;
  const char* label;
};
const std::array<OrthoglideCase, 4> kOrthoglideCases = {
    {{mechanisms::OrthoglideArchitecture::kPUU, 0.0, "3-PUU Q0"},
     {mechanisms::OrthoglideArchitecture::kPUU, -73.65, "3-PUU Q1"},
     {mechanisms::OrthoglideArchitecture::kPRPaR, 0.0, "3-PRPaR Q0"},
     {mechanisms::OrthoglideArchitecture::kPRPaR, -73.65, "3-PRPaR Q1"}}};

const OrthoglideCase& orthoglide_case(const benchmark::State& state) {
  return kOrthoglideCases[static_cast<std::size_t>(state.range(0))];
}

Mat6 orthoglide_vjm(const OrthoglideCase& c) {
  const std::vector<vjm::Chain> chains =
      *mechanisms::orthoglide_chains({}, c.architecture, mechanisms::paper_table_point(c.table_mm));
  return vjm::platform_unloaded_stiffness(chains)->stiffness;
}

Mat6 orthoglide_msa(const OrthoglideCase& c, msa::Workspace& ws) {
  const msa::Structure s = *mechanisms::orthoglide_frame({}, c.architecture, mechanisms::paper_table_point(c.table_mm));
  return msa::cartesian_stiffness(s, ws, *s.report_node())->stiffness;
}

void set_orthoglide_counters(benchmark::State& state, const OrthoglideCase& c) {
  msa::Workspace ws;
  const Mat6 Km = orthoglide_msa(c, ws);
  state.counters["max_rel_diff"] = (orthoglide_vjm(c) - Km).cwiseAbs().maxCoeff() / Km.cwiseAbs().maxCoeff();
  state.SetLabel(c.label);
}

void BM_OrthoglideVjm(benchmark::State& state) {
  const OrthoglideCase& c = orthoglide_case(state);
  for (auto _ : state) benchmark::DoNotOptimize(orthoglide_vjm(c));
  set_orthoglide_counters(state, c);
}

void BM_OrthoglideMsa(benchmark::State& state) {
  const OrthoglideCase& c = orthoglide_case(state);
  msa::Workspace ws;  // symbolic analysis reused across postures, as in a sweep
  for (auto _ : state) benchmark::DoNotOptimize(orthoglide_msa(c, ws));
  set_orthoglide_counters(state, c);
}

BENCHMARK(BM_OrthoglideVjm)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OrthoglideMsa)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace kinestat

BENCHMARK_MAIN();
