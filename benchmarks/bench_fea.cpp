// FEA link stiffness: CGAL meshing, parallel assembly, CHOLMOD factorization and the six solves
// at ~30k / 90k / 290k dofs (structured quadratic-tet bars, n = 4, 6, 9 cells across the 20 mm
// side). The label shows the backend (with its BLAS) and the ordering CHOLMOD chose. BM_DenseGemm
// measures the dense dgemm rate of the same BLAS (the one CHOLMOD loaded), the ceiling of the
// supernodal factorization's flop rate; BM_FactorizeAndSolve measures it again in its own process
// (gemm_GFlop_per_s) and reports the factorization's share of it (factor_share_of_gemm).
// For each phase (assembly, analysis, factor, solves) it reports the process's wall, user and
// system time, voluntary and involuntary context switches and minor page faults (getrusage), and
// the thread count during the factorization (/proc/self/status): these survive a busy machine
// better than wall times (benchmarks/README.md, "Factorization rate"). peak_rss_MB is the process's
// peak so far (ru_maxrss): run one size per process (--benchmark_filter='FactorizeAndSolve/9/') to
// get that size's peak.
#include <benchmark/benchmark.h>
#include <dlfcn.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "bar_mesh.hpp"
#include "fea/elasticity_assembly.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/surface_mesher.hpp"
#include "kinestat/fea/tet_element.hpp"
#include "kinestat/fea/tet_mesh.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"

namespace {

using namespace kinestat;

const Material kSteel = Material::from_E_nu("steel", 210e9, 0.3);

// What the process spent between two snapshots (getrusage is per process: all threads).
struct ProcessSnapshot {
  std::chrono::steady_clock::time_point wall = std::chrono::steady_clock::now();
  rusage usage = [] {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u;
  }();
};

double seconds(const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); }

// Counters "<phase>_wall_s", "_user_s", "_sys_s", "_vcsw", "_ivcsw", "_minflt"; returns the wall time.
double add_phase_counters(benchmark::State& state, const std::string& phase, const ProcessSnapshot& a,
                          const ProcessSnapshot& b) {
  const double wall = std::chrono::duration<double>(b.wall - a.wall).count();
  state.counters[phase + "_wall_s"] = wall;
  state.counters[phase + "_user_s"] = seconds(b.usage.ru_utime) - seconds(a.usage.ru_utime);
  state.counters[phase + "_sys_s"] = seconds(b.usage.ru_stime) - seconds(a.usage.ru_stime);
  state.counters[phase + "_vcsw"] = static_cast<double>(b.usage.ru_nvcsw - a.usage.ru_nvcsw);
  state.counters[phase + "_ivcsw"] = static_cast<double>(b.usage.ru_nivcsw - a.usage.ru_nivcsw);
  state.counters[phase + "_minflt"] = static_cast<double>(b.usage.ru_minflt - a.usage.ru_minflt);
  return wall;
}

// Threads of this process now (TBB workers, OpenBLAS's pthreads, OpenMP teams), from /proc/self/status.
int thread_count() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Threads:", 0) == 0) return std::atoi(line.c_str() + 8);
  return -1;
}

double peak_rss_megabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux: kilobytes
}

// Fortran BLAS dgemm, found at run time: the program links BLAS only through CHOLMOD.
using Dgemm = void(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                   const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                   const double* beta, double* c, const int* ldc, std::size_t transa_len, std::size_t transb_len);

// C = A B with n x n matrices: Gflop/s of the best of `repeats` (2 n^3 flops each, wall time: the
// BLAS runs on all cores); 0 when no BLAS is loaded.
double dense_gemm_gflops(int n, int repeats) {
  auto* dgemm = reinterpret_cast<Dgemm*>(dlsym(RTLD_DEFAULT, "dgemm_"));
  if (dgemm == nullptr) return 0.0;
  const MatX A = MatX::Random(n, n), B = MatX::Random(n, n);
  MatX C(n, n);
  const double one = 1.0, zero = 0.0;
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    dgemm("N", "N", &n, &n, &n, &one, A.data(), &n, B.data(), &n, &zero, C.data(), &n, 1, 1);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return 2.0 * n * n * static_cast<double>(n) / best * 1e-9;
}

void BM_DenseGemm(benchmark::State& state) {
  double gflops = 0.0;
  for (auto _ : state) gflops = dense_gemm_gflops(static_cast<int>(state.range(0)), 1);
  if (gflops == 0.0) state.SkipWithError("dgemm_ is not loaded in this process");
  state.counters["GFlop_per_s"] = gflops;
}
BENCHMARK(BM_DenseGemm)->Arg(3000)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Meshing(benchmark::State& state) {
  fea::MeshingOptions o;
  o.size = state.range(0) * 1e-3;
  const std::string path = std::string(KINESTAT_SOURCE_DIR) + "/meshes/tube.off";
  int elements = 0;
  for (auto _ : state) {
    auto mesh = fea::mesh_surface_file(path, o);
    if (!mesh.ok()) state.SkipWithError(mesh.status().message().c_str());
    elements = mesh->num_elements();
  }
  state.SetLabel(fmt::format("tube.off, size {} mm, {} tets", state.range(0), elements));
}
BENCHMARK(BM_Meshing)->Arg(6)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_Assembly(benchmark::State& state) {
  const fea::TetMesh mesh = bench::bar(static_cast<int>(state.range(0)));
  const fea::DofMap map = bench::clamped_bar_map(mesh);
  const std::vector<Mat6> D = {fea::elasticity_matrix(kSteel)};
  for (auto _ : state) {
    solver::SparseMatrix K;
    benchmark::DoNotOptimize(fea::assemble_stiffness(mesh, D, {}, map, &K));
  }
  state.counters["dofs"] = map.num_dofs;
  state.counters["elements"] = mesh.num_elements();
}
BENCHMARK(BM_Assembly)->Arg(4)->Arg(6)->Arg(9)->Unit(benchmark::kMillisecond);

// The solver path of link-stiffness (meshing excluded): assembly, analysis + numeric factorization
// (CHOLMOD times the two), the six solves; each phase with its process counters (see the top).
void BM_FactorizeAndSolve(benchmark::State& state) {
  const fea::TetMesh mesh = bench::bar(static_cast<int>(state.range(0)));
  const fea::DofMap map = bench::clamped_bar_map(mesh);
  const std::vector<Mat6> D = {fea::elasticity_matrix(kSteel)};
  // The BLAS ceiling of this process, measured before the factorization (the same threads, no
  // other work of ours running).
  const double gemm_gflops = dense_gemm_gflops(3000, 3);
  MatX F = MatX::Zero(map.num_dofs, 6), X;
  F.middleRows<6>(map.reference_dof).setIdentity();
  solver::FactorizationReport report;
  std::string backend;
  double path_seconds = 0.0, first_path_seconds = 0.0, first_factor_seconds = 0.0;
  int factor_threads = 0;
  for (auto _ : state) {
    const ProcessSnapshot s0;
    solver::SparseMatrix K;
    const bool assembled = fea::assemble_stiffness(mesh, D, {}, map, &K).ok();
    const ProcessSnapshot s1;
    auto chol = solver::make_sparse_cholesky();
    backend = chol->backend_description();
    if (!assembled || !chol->Factorize(K, &report).ok()) state.SkipWithError("assembly or factorization failed");
    factor_threads = thread_count();
    const ProcessSnapshot s2;
    (void)chol->Solve(F, &X);
    const ProcessSnapshot s3;
    path_seconds = add_phase_counters(state, "assembly", s0, s1) + add_phase_counters(state, "factorize", s1, s2) +
                   add_phase_counters(state, "solves", s2, s3);
    if (first_path_seconds == 0.0) {
      first_path_seconds = path_seconds;
      first_factor_seconds = report.factor_seconds;
    }
  }
  state.counters["dofs"] = map.num_dofs;
  state.counters["nnz_L"] = static_cast<double>(report.nnz_factor);
  state.counters["GFlop"] = report.flops * 1e-9;
  state.counters["analyze_s"] = report.analyze_seconds;
  state.counters["factor_s"] = report.factor_seconds;
  state.counters["factor_GFlop_per_s"] = report.flops * 1e-9 / report.factor_seconds;
  state.counters["gemm_GFlop_per_s"] = gemm_gflops;
  state.counters["factor_share_of_gemm"] =
      gemm_gflops > 0 ? report.flops * 1e-9 / report.factor_seconds / gemm_gflops : 0.0;
  state.counters["path_s"] = path_seconds;  // assembly + analysis + factorization + six solves
  // The first pass of the process: its factor's memory is new to the process, and this VM's host
  // backs such memory again on first touch (benchmarks/README.md, "First touch in this VM").
  state.counters["first_factor_s"] = first_factor_seconds;
  state.counters["first_factor_GFlop_per_s"] = report.flops * 1e-9 / first_factor_seconds;
  state.counters["first_path_s"] = first_path_seconds;
  state.counters["threads"] = factor_threads;
  state.counters["peak_rss_MB"] = peak_rss_megabytes();
  state.SetLabel(fmt::format("{}; ordering {}", backend, report.ordering));
}
// 4, 6, 9: ~28k, 88k, 296k dofs, two passes (the counters without "first_" are the second's: a
// sweep's or a second link's, whose factor memory the process has already touched). 14: ~1.05M dofs,
// ~16 GB and minutes, one pass: skip it with --benchmark_filter=-Million, or measure it alone with
// --benchmark_filter=Million (peak memory is per process, so each size is best run in its own process).
BENCHMARK(BM_FactorizeAndSolve)->Arg(4)->Arg(6)->Arg(9)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_FactorizeAndSolve)
    ->Name("BM_FactorizeAndSolveMillion")
    ->Arg(14)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
