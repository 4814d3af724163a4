// Workspace-map throughput: postures per second of the sweep kernels (make_five_bar_kernel,
// make_orthoglide_kernel) over a realistic grid, on one core and on all cores (evaluate_postures
// with threads = 1 and 0), and the ratio against today's per-posture path (the reference kernels:
// msa::cartesian_stiffness with a reused workspace, the VJM platform stiffness of `kinestat vjm`)
// measured in the same run on a subsample of the same grid. Ends with the process's user, system
// and wall time (getrusage).
//
// Not a Google Benchmark: one line per kernel with the figures the map needs (issue 8).
// The CPU-time rate (postures per second of the process's user + system time) is what one core
// gives even on a busy machine; the wall-time rates are the figures to record on a quiet one.
// The loaded kernels: a table of their own, warm-started along the map's serpentine path against
// the same kernel from scratch and the unloaded kernel, in the same run. The loaded and the generic
// robot kernels are also timed started at each posture's own answer (repeated()): the ceiling of any
// warm start, against which the issues' targets compare (benchmarks/README.md).
// Run: ./build/benchmarks/bench_map [--min-time S] [--reference-points N] [--scratch-points N]
//      [--loaded-only 1] [--robots-only 1]
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/orthoglide_kernel.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::mechanisms {
namespace {

using Clock = std::chrono::steady_clock;

struct Settings {
  double min_time = 1.0;        // s of repeated sweeps per measurement (the best sweep counts)
  int reference_points = 2000;  // subsample for the slow reference path
  int scratch_points = 4000;    // subsample for the loaded kernels from scratch
  bool loaded_only = false;     // only the loaded-mode table
  bool robots_only = false;     // only the robot-file table
};

double seconds(const timeval& t) { return t.tv_sec + 1e-6 * t.tv_usec; }

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return seconds(u.ru_utime) + seconds(u.ru_stime);
}

struct Rate {
  double wall = 0.0;  // postures per second of wall time, best sweep
  double cpu = 0.0;   // postures per second of the process's CPU time (user + system), all sweeps
};

// Repeated sweeps lasting together at least `min_time` (at least one).
Rate rate(const PostureKernel& kernel, const std::vector<Vec3>& points, int threads, double min_time,
          PointOrder order = PointOrder::kIndependent) {
  std::vector<PostureResult> results;
  Rate r;
  double total = 0.0;
  const double cpu0 = cpu_seconds();
  std::size_t evaluated = 0;
  do {
    const auto t0 = Clock::now();
    evaluate_postures(kernel, points, results, threads, {}, order);
    const double dt = std::chrono::duration<double>(Clock::now() - t0).count();
    total += dt;
    evaluated += points.size();
    r.wall = std::max(r.wall, points.size() / dt);
  } while (total < min_time);
  r.cpu = evaluated / (cpu_seconds() - cpu0);
  return r;
}

std::vector<Vec3> every_nth(const std::vector<Vec3>& points, int count) {
  const std::size_t step = std::max<std::size_t>(1, points.size() / std::max(1, count));
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < points.size(); i += step) out.push_back(points[i]);
  return out;
}

// 400 of the points, each 100 times in a row: along PointOrder::kPath every evaluation but the first
// of each starts from its own answer (the extrapolation through equal points is the last answer), so
// that the rate is the most any warm start (a better predictor, a finer grid) could give.
constexpr int kRepeats = 100;
std::vector<Vec3> repeated(const std::vector<Vec3>& points) {
  std::vector<Vec3> out;
  for (const Vec3& p : every_nth(points, 400)) out.insert(out.end(), kRepeats, p);
  return out;
}

void report(const PostureKernel& fast, const PostureKernel& reference, const std::vector<Vec3>& points,
            const Settings& s) {
  std::vector<PostureResult> results;
  evaluate_postures(fast, points, results, 1);
  int counts[4] = {0, 0, 0, 0};
  for (const PostureResult& r : results) ++counts[static_cast<int>(r.status)];
  const Rate one = rate(fast, points, 1, s.min_time);
  const Rate all = rate(fast, points, 0, s.min_time);
  const Rate ref = rate(reference, every_nth(points, s.reference_points), 1, 0.0);
  fmt::print("{:<46} {:>6} {:>6} {:>5} {:>6} | {:>9.0f} {:>9.0f} {:>9.0f} {:>5.2f}x | {:>8.0f} {:>6.0f}x {:>6.0f}x\n",
             fast.description(), points.size(), counts[0], counts[2], counts[1], one.wall, one.cpu, all.wall,
             all.wall / one.wall, ref.wall, one.wall / ref.wall, one.cpu / ref.cpu);
  std::fflush(stdout);
}

// Loaded mode: the kernel along the serpentine path of the grid (PointOrder::kPath, warm starts, as
// compute_workspace_map runs it) against the same kernel from scratch at every posture (kIndependent,
// on a subsample of the same grid) and the unloaded kernel on the same path, in the same run; the
// mean Newton steps per reachable posture of each; and the same kernel started at each posture's own
// equilibrium (repeated()), with its steps.
void report_loaded(const PostureKernel& loaded, const PostureKernel& unloaded, const std::vector<Vec3>& path,
                   const Settings& s) {
  const auto mean_steps = [](const std::vector<PostureResult>& results, int counts[4]) {
    double steps = 0.0, reached = 0.0;
    for (const PostureResult& r : results) {
      if (counts) ++counts[static_cast<int>(r.status)];
      if (r.status == PostureStatus::kUnreachable) continue;
      steps += r.newton_iterations;
      reached += 1.0;
    }
    return reached > 0 ? steps / reached : 0.0;
  };
  std::vector<PostureResult> results;
  int counts[4] = {0, 0, 0, 0};
  evaluate_postures(loaded, path, results, 1, {}, PointOrder::kPath);
  const double warm_steps = mean_steps(results, counts);
  const std::vector<Vec3> sample = every_nth(path, s.scratch_points);
  evaluate_postures(loaded, sample, results, 1);
  const double scratch_steps = mean_steps(results, nullptr);
  const std::vector<Vec3> again = repeated(path);
  evaluate_postures(loaded, again, results, 1, {}, PointOrder::kPath);
  const double exact_steps = mean_steps(results, nullptr);
  const Rate plain = rate(unloaded, path, 1, s.min_time, PointOrder::kPath);
  const Rate scratch = rate(loaded, sample, 1, s.min_time);
  const Rate warm = rate(loaded, path, 1, s.min_time, PointOrder::kPath);
  const Rate warm_all = rate(loaded, path, 0, s.min_time, PointOrder::kPath);
  const Rate exact = rate(loaded, again, 1, s.min_time, PointOrder::kPath);
  fmt::print(
      "{:<50} {:>6} {:>6} | {:>9.0f} {:>9.0f} {:>9.0f} | {:>9.0f} {:>9.0f} {:>9.0f} | {:>9.0f} | {:>6.1f}x {:>6.1f}x "
      "{:>5.2f}x | {:>5.1f} {:>5.1f} | {:>9.0f} {:>5.1f}\n",
      loaded.description(), counts[0], counts[3], plain.wall, scratch.wall, warm.wall, plain.cpu, scratch.cpu, warm.cpu,
      warm_all.wall, warm.cpu / scratch.cpu, plain.cpu / warm.cpu, warm_all.wall / warm.wall, scratch_steps, warm_steps,
      exact.cpu, exact_steps);
  std::fflush(stdout);
}

std::vector<Vec3> plane_grid(double x0, double x1, double y0, double y1, int n) {
  std::vector<Vec3> pts;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) pts.emplace_back(x0 + (x1 - x0) * i / (n - 1), y0 + (y1 - y0) * j / (n - 1), 0.0);
  return pts;
}

std::vector<Vec3> cube_grid(double lo, double hi, int n) {
  std::vector<Vec3> pts;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const auto c = [&](int a) { return lo + (hi - lo) * a / (n - 1); };
        pts.emplace_back(c(i), c(j), c(k));
      }
  return pts;
}

void unloaded_tables(const Settings& s);
void loaded_table(const Settings& s);
void robot_table(const Settings& s);

int run(const Settings& s) {
  const auto t0 = Clock::now();
  fmt::print(
      "hardware threads: {}; best of sweeps lasting >= {:g} s; reference on <= {} points of each grid\n"
      "columns: postures/s on 1 core (wall, best sweep; and per second of process CPU time), on all "
      "cores (wall), their ratio; the reference path on 1 core (wall) and the speed-up (wall; CPU)\n",
      std::thread::hardware_concurrency(), s.min_time, s.reference_points);
  fmt::print("{:<46} {:>6} {:>6} {:>5} {:>6} | {:>9} {:>9} {:>9} {:>6} | {:>8} {:>7} {:>7}\n", "kernel", "points", "ok",
             "sing.", "unrch.", "1 core/s", "1 cpu/s", "all/s", "ratio", "ref/s", "vs ref", "(cpu)");

  if (!s.loaded_only && !s.robots_only) unloaded_tables(s);
  if (!s.loaded_only) robot_table(s);
  if (!s.robots_only) loaded_table(s);
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
  fmt::print("process: user {:.2f} s, system {:.2f} s, wall {:.2f} s\n", seconds(u.ru_utime), seconds(u.ru_stime),
             wall);
  return 0;
}

void unloaded_tables(const Settings& s) {
  // Five-bar: a 100 x 100 grid over the bounding box of its workspace (both legs' reach).
  FiveBarKernelOptions fb;
  const double reach = fb.params.r1 + fb.params.r2;
  const double h = std::sqrt(reach * reach - fb.params.r3 * fb.params.r3);
  const std::vector<Vec3> plane = plane_grid(fb.params.r3 - reach, reach - fb.params.r3, -h, h, 100);
  for (StiffnessMethod m : {StiffnessMethod::kMsa, StiffnessMethod::kVjm}) {
    fb.method = m;
    report(*make_five_bar_kernel(fb), *make_reference_five_bar_kernel(fb), plane, s);
  }

  // Orthoglide: the 200 mm design cube (the tables' Q1..Q2 on the kinematics' axes) at 5 mm, 41^3 points.
  const std::vector<Vec3> cube = cube_grid(-0.12635, 0.07365, 41);
  for (OrthoglideArchitecture a : {OrthoglideArchitecture::kPUU, OrthoglideArchitecture::kPRPaR}) {
    OrthoglideKernelOptions o;
    o.architecture = a;
    report(*make_orthoglide_kernel(o), *make_reference_orthoglide_kernel(o), cube, s);
  }
}

// The generic kernel of robot files (make_robot_kernel, models/robots/) along the map's serpentine
// path: the five-bar and the Orthoglide 3-PUU and 3-PRPaR beside their built-in kernels on the same
// grids (the same models: tests/io/robot_test.cpp), the Delta and the hexapod over their files'
// workspaces; the generic kernel also at its reachable postures started from their own closures.
void robot_table(const Settings& s) {
  fmt::print(
      "\ngeneric robot kernel (robot files), unloaded, along the serpentine path: postures/s on 1 core (wall, "
      "best sweep; per second of process CPU time), on all cores (wall), all/1; the built-in kernel on the "
      "same grid and path (1 core wall; CPU) and generic/built-in (CPU); the generic kernel started at each "
      "reachable posture's own closure (400 of them, each {} times in a row: the most a warm start can give), "
      "CPU rate, and against the built-in kernel on the same points (CPU)\n",
      kRepeats);
  fmt::print("{:<46} {:>6} {:>6} | {:>9} {:>9} {:>9} {:>6} | {:>9} {:>9} {:>8} | {:>9} {:>7}\n", "kernel", "points",
             "ok", "1 core/s", "1 cpu/s", "all/s", "all/1", "built-in", "(cpu)", "gen/bi", "exact cpu", "ex/bi");
  const auto grid_path = [](const Vec3& lo, const Vec3& hi, std::array<int, 3> n) {
    MapGrid g;
    g.origin = lo;
    g.dimensions = n;
    for (int a = 0; a < 3; ++a) g.spacing(a) = n[a] > 1 ? (hi(a) - lo(a)) / (n[a] - 1) : 1.0;
    std::vector<Vec3> path(g.num_points());
    for (std::size_t k = 0; k < path.size(); ++k) path[k] = g.point(g.path_index(k));
    return path;
  };
  const auto row = [&](const std::string& file, const std::vector<Vec3>& path, const PostureKernel* builtin) {
    auto model = io::read_robot_model(std::string(KINESTAT_SOURCE_DIR) + "/models/robots/" + file);
    if (!model.ok()) {
      fmt::print("{}: {}\n", file, model.status().message());
      return;
    }
    RobotKernelOptions o;
    o.model = std::make_shared<const RobotModel>(std::move(*model));
    const auto kernel = make_robot_kernel(o);
    std::vector<PostureResult> results;
    evaluate_postures(*kernel, path, results, 1, {}, PointOrder::kPath);
    std::vector<Vec3> reachable;
    for (std::size_t i = 0; i < path.size(); ++i)
      if (results[i].status == PostureStatus::kOk) reachable.push_back(path[i]);
    const Rate one = rate(*kernel, path, 1, s.min_time, PointOrder::kPath);
    const Rate all = rate(*kernel, path, 0, s.min_time, PointOrder::kPath);
    const std::vector<Vec3> again = repeated(reachable);
    const Rate exact = rate(*kernel, again, 1, s.min_time, PointOrder::kPath);
    // The built-in kernel on the whole grid and on the exact start's points (a grid mostly out of
    // reach, as the five-bar's, is cheap on both).
    Rate bi, bi_again;
    if (builtin) {
      bi = rate(*builtin, path, 1, s.min_time, PointOrder::kPath);
      bi_again = rate(*builtin, again, 1, s.min_time, PointOrder::kPath);
    }
    fmt::print(
        "{:<46} {:>6} {:>6} | {:>9.0f} {:>9.0f} {:>9.0f} {:>5.2f}x | {:>9.0f} {:>9.0f} {:>7.3f}x | {:>9.0f} "
        "{:>6.3f}x\n",
        kernel->description(), path.size(), reachable.size(), one.wall, one.cpu, all.wall, all.wall / one.wall, bi.wall,
        bi.cpu, builtin ? one.cpu / bi.cpu : 0.0, exact.cpu, builtin ? exact.cpu / bi_again.cpu : 0.0);
    std::fflush(stdout);
  };
  FiveBarKernelOptions fb;
  fb.mode = WorkingMode{1, -1};
  fb.method = StiffnessMethod::kVjm;
  row("five_bar.yaml", grid_path(Vec3(-0.2, 0.0, 0.0), Vec3(0.2, 0.2, 0.0), {81, 41, 1}),
      make_five_bar_kernel(fb).get());
  OrthoglideKernelOptions og;
  row("orthoglide_puu.yaml", grid_path(Vec3::Constant(-0.1), Vec3::Constant(0.1), {21, 21, 21}),
      make_orthoglide_kernel(og).get());
  og.architecture = OrthoglideArchitecture::kPRPaR;
  row("orthoglide_prpar.yaml", grid_path(Vec3::Constant(-0.1), Vec3::Constant(0.1), {21, 21, 21}),
      make_orthoglide_kernel(og).get());
  row("delta.yaml", grid_path(Vec3(-0.4, -0.4, -1.0), Vec3(0.4, 0.4, -0.5), {33, 33, 21}), nullptr);
  row("hexapod.yaml", grid_path(Vec3(-0.15, -0.15, 0.7), Vec3(0.15, 0.15, 0.9), {21, 21, 11}), nullptr);
}

void loaded_table(const Settings& s) {
  // Loaded mode: a wrench and the tables' wrench-free displacement case, on the same 41^3 cube,
  // along its serpentine path (the map's order).
  MapGrid box;
  box.origin = Vec3::Constant(-0.12635);
  box.spacing = Vec3::Constant(0.005);
  box.dimensions = {41, 41, 41};
  std::vector<Vec3> path(box.num_points());
  for (std::size_t k = 0; k < path.size(); ++k) path[k] = box.point(box.path_index(k));
  fmt::print(
      "\nloaded mode along the serpentine path of the same cube ({} points); postures/s on 1 core of the "
      "unloaded kernel, the loaded kernel from scratch at every posture (on <= {} of the points) and "
      "warm-started, per second of wall time (best sweep) and of process CPU time (all sweeps); warm-started "
      "on all cores (wall); ratios warm/scratch and unloaded/warm of the CPU rates (robust on a shared "
      "machine), all cores/1 core; mean Newton steps per posture from scratch and warm; started at each "
      "posture's own equilibrium (400 points, each {} times in a row: the most a warm start can give), CPU rate "
      "and steps\n",
      path.size(), s.scratch_points, kRepeats);
  fmt::print(
      "{:<50} {:>6} {:>6} | {:>9} {:>9} {:>9} | {:>9} {:>9} {:>9} | {:>9} | {:>7} {:>7} {:>6} | {:>5} {:>5} | {:>9} "
      "{:>5}\n",
      "kernel", "ok", "failed", "unloaded", "scratch", "warm", "u cpu", "s cpu", "w cpu", "warm all", "w/s", "u/w",
      "all/1", "steps", "warm", "exact cpu", "steps");
  for (OrthoglideArchitecture a : {OrthoglideArchitecture::kPUU, OrthoglideArchitecture::kPRPaR}) {
    OrthoglideKernelOptions o;
    o.architecture = a;
    const std::unique_ptr<PostureKernel> unloaded = make_orthoglide_kernel(o);
    o.wrench = (Vec6() << 100.0, -50.0, 80.0, 0.0, 0.0, 0.0).finished();
    report_loaded(*make_orthoglide_kernel(o), *unloaded, path, s);
    o.wrench = (Vec6() << 0.0, 0.0, -500.0, 0.0, 0.0, 0.0).finished();  // the issue's `kinestat map` load
    report_loaded(*make_orthoglide_kernel(o), *unloaded, path, s);
    o.wrench.reset();
    o.displacement = (Vec6() << -5e-4, -5e-4, -5e-4, 0.0, 0.0, 0.0).finished();
    report_loaded(*make_orthoglide_kernel(o), *unloaded, path, s);
  }
}

}  // namespace
}  // namespace kinestat::mechanisms

int main(int argc, char** argv) {
  kinestat::mechanisms::Settings s;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--min-time") == 0) {
      s.min_time = std::atof(argv[i + 1]);
    } else if (std::strcmp(argv[i], "--reference-points") == 0) {
      s.reference_points = std::atoi(argv[i + 1]);
    } else if (std::strcmp(argv[i], "--scratch-points") == 0) {
      s.scratch_points = std::atoi(argv[i + 1]);
    } else if (std::strcmp(argv[i], "--robots-only") == 0) {
      s.robots_only = std::atoi(argv[i + 1]) != 0;
    } else if (std::strcmp(argv[i], "--loaded-only") == 0) {
      s.loaded_only = std::atoi(argv[i + 1]) != 0;
    } else {
      fmt::print(stderr,
                 "bench_map: unknown option {}; use --min-time S, --reference-points N, --scratch-points N, "
                 "--loaded-only 0|1\n",
                 argv[i]);
      return 2;
    }
  }
  return kinestat::mechanisms::run(s);
}
