// MSA performance: assembly + factorization + solve against model size, and the per-posture cost of
// the five-bar with the symbolic analysis reused (one Workspace) against a fresh analysis.
// Run: ./build/benchmarks/bench_msa   (figures and machine: benchmarks/README.md)
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat {
namespace {

// A 3D lattice frame of n x n x h nodes (steel tubes, 0.2 m bays), clamped at its base, with a
// lateral and a vertical load case at the top corner: ~6 n^2 h dofs.
msa::Structure lattice(int n, int h) {
  msa::Structure s;
  const int m = s.add_material({"steel", 2.1e11, 0.81e11});
  const int c = s.add_section(tube_section(0.03, 0.003));
  auto id = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int k = 0; k < h; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) s.add_node(fmt::format("{}_{}_{}", i, j, k), Vec3(i, j, k) * 0.2);
  int b = 0;
  for (int k = 0; k < h; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = id(i, j, k);
        auto add = [&](int other) {
          msa::Beam beam;
          beam.id = fmt::format("b{}", b++);
          beam.node1 = a;
          beam.node2 = other;
          beam.material = m;
          beam.section = c;
          s.add_beam(beam);
        };
        if (i + 1 < n) add(id(i + 1, j, k));
        if (j + 1 < n) add(id(i, j + 1, k));
        if (k + 1 < h) add(id(i, j, k + 1));
      }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) s.add_support({id(i, j, 0), msa::kAllDofs, Mat3::Identity()});
  const int top = id(n - 1, n - 1, h - 1);
  s.add_load_case({"lateral", {{top, (Vec6() << 1e3, 0, 0, 0, 0, 0).finished()}}, {}});
  s.add_load_case({"vertical", {{top, (Vec6() << 0, 0, -1e3, 0, 0, 0).finished()}}, {}});
  return s;
}

void BM_LatticeSolve(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const msa::Structure s = lattice(n, n);
  msa::SolveOptions opt;
  opt.max_dofs_for_global_indices = 0;  // the dense eigen-decomposition is not what is measured
  msa::Solution sol;
  for (auto _ : state) {
    sol = msa::solve(s, opt);
    benchmark::DoNotOptimize(sol.cases.data());
  }
  if (!sol.status.ok()) state.SkipWithError(sol.status.message().c_str());
  state.counters["dofs"] = sol.num_free_dofs;
  state.counters["nnz_L"] = static_cast<double>(sol.factorization.nnz_factor);
  state.counters["Mflop"] = sol.factorization.flops / 1e6;
  state.counters["assembly_s"] = sol.assembly_seconds;
  state.counters["factor_s"] = sol.factorization.factor_seconds;
  state.counters["analyse_s"] = sol.factorization.analyze_seconds;
  state.SetLabel(
      fmt::format("{} {}", sol.factorization.supernodal ? "supernodal" : "simplicial", sol.factorization.ordering));
}
// n^3 nodes: 6x6x6 -> 1.1k dofs, 12^3 -> 9.5k, 20^3 -> 46k, 26^3 -> 101k dofs.
BENCHMARK(BM_LatticeSolve)->Arg(6)->Arg(12)->Arg(20)->Arg(26)->Unit(benchmark::kMillisecond);

// Five-bar posture sweep: theta2 from 95 to 135 deg with theta1 = 80 deg, one posture per iteration.
void five_bar_sweep(benchmark::State& state, bool reuse) {
  const mechanisms::FiveBarParams p;
  msa::Workspace shared;
  int i = 0;
  for (auto _ : state) {
    const double t2 = (95.0 + (i++ % 40)) * std::numbers::pi / 180.0;
    auto s = mechanisms::make_five_bar_structure(p, 80.0 * std::numbers::pi / 180.0, t2, mechanisms::Assembly::kUp);
    msa::Workspace fresh;
    const msa::Solution sol = msa::solve(*s, reuse ? shared : fresh);
    benchmark::DoNotOptimize(sol.cartesian);
  }
  state.counters["symbolic_analyses"] = shared.num_symbolic_analyses();
}
void BM_FiveBarPostureReuse(benchmark::State& state) { five_bar_sweep(state, true); }
void BM_FiveBarPostureFresh(benchmark::State& state) { five_bar_sweep(state, false); }
BENCHMARK(BM_FiveBarPostureReuse)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FiveBarPostureFresh)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace kinestat

BENCHMARK_MAIN();
