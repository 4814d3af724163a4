// kinestat design orthoglide --cube C --mu MU [--strategy 1|2|3] [--vtk DIR] [--encoder-offsets E1,E2]
//                            [--json FILE|-]
// Geometric synthesis of the Orthoglide (Pashkevich, Wenger, Chablat 2005, Table 3): link length,
// joint limits and cube location for a cube of edge C and transmission factors in [MU, 1/MU]; the
// paper's other analyses (section 5.2 switch points, Fig. 3 and Table 2 volumes, encoder offsets).
//
// kinestat design fivebar --r1 A:B --r2 C:D --steps N --region X0:X1,Y0:Y1 [--min-stiffness K] ...
// Design sweep of the five-bar (mechanisms/five_bar_design_sweep.hpp): the share of a region that
// each design (r1, r2) reaches singularity-free and stiffer than K; the best design; VTI, PNG, JSON.
//
// kinestat design ROBOT.yaml --param NAME=LO:HI ... --steps N [--box X0:X1,Y0:Y1,Z0:Z1] --step MM [--load D | --wrench W]
//                            --min-stiffness K [--json FILE|-] [--vti FILE] [--quiet]
// Design sweep of a robot file (mechanisms/robot_design_sweep.hpp): every design of the grid of the
// named parameters (the file re-read with their values, io::read_robot_model), its map of one
// region, its volume (area) with k_t_min >= K; the best design. Under mpirun the designs are split
// across the ranks; rank 0 writes.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <optional>
#include <ostream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/command_output.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/io/orthoglide_results_json.hpp"
#include "cli/grid_options.hpp"
#include "kinestat/cli/app.hpp"
#include "kinestat/io/five_bar_design_output.hpp"
#include "kinestat/io/robot_design_output.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/io/workspace_map_png.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/workspace_vtk.hpp"
#include "kinestat/mechanisms/five_bar_design_sweep.hpp"
#include "kinestat/mechanisms/orthoglide_design.hpp"
#include "kinestat/mechanisms/robot_design_sweep.hpp"
#include "kinestat/solver/parallel.hpp"

namespace kinestat::cli {
namespace {

using units::kMm;  // lengths are printed in mm

struct DesignArgs {
  double cube_mm = 0.0;
  double mu = 0.0;
  std::optional<int> strategy;  // all three when absent
  std::string vtk_dir;
  int vtk_grid = 21;
  int search_points = 41;
  std::vector<double> encoder_offsets_mm = {5.0, 10.0};  // section 6's examples
  double max_points = mechanisms::kDefaultMaxSearchPoints;
  OutputOptions out;
};

// Grid of the volume fractions of Fig. 3 and Table 2 (n^3 cells over [-L, L]^3; ~0.5 % from the
// paper's own ray method, tests/mechanisms/orthoglide_design_test.cpp).
constexpr int kVolumeGrid = 80;

const char* strategy_summary(int s) {
  switch (s) {
    case 1: return "cube vertices at Q+ and Q-, upper joint limit raised to reach the cube";
    case 2: return "joint limits at Q+ and Q-, the largest cube inside the joint-bounded workspace";
    default: return "joint limits so that the whole joint-bounded workspace meets the bounds, cube inside it";
  }
}

std::string range(const mechanisms::TransmissionRange& r) {
  if (!(r.max < std::numeric_limits<double>::infinity())) return fmt::format("[{:.3f}, inf), singular", r.min);
  return fmt::format("[{:.3f}, {:.3f}]", r.min, r.max);
}

void print_design(std::ostream& out, const mechanisms::OrthoglideDesign& d,
                  const mechanisms::OrthoglideDesignCheck& check) {
  const double L = d.link_length;
  out << fmt::format("strategy {}: {}\n", d.strategy, strategy_summary(d.strategy));
  out << fmt::format("  link length L               {:.1f} mm\n", L / kMm);
  out << fmt::format("  joint limits rho            [{:.1f}, {:.1f}] mm (stroke {:.1f} mm)\n", d.rho_min / kMm,
                     d.rho_max / kMm, (d.rho_max - d.rho_min) / kMm);
  out << fmt::format("  cube p_x, p_y, p_z          [{:.1f}, {:.1f}] mm (isotropic point at p = 0, rho = L)\n",
                     d.p_min / kMm, d.p_max / kMm);
  if (std::isfinite(d.joint_sum_limit))
    out << fmt::format("  software joint limit        rho_x + rho_y + rho_z <= {:.1f} mm (= 3 rho(Q+); the joint box "
                       "reaches the parallel singularity)\n",
                       d.joint_sum_limit / kMm);
  out << fmt::format("  unit manipulator (L = 1)    rho in [{:.4f}, {:.4f}], p in [{:.4f}, {:.4f}]\n", d.rho_min / L,
                     d.rho_max / L, d.p_min / L, d.p_max / L);
  if (std::isfinite(d.joint_sum_limit))
    out << fmt::format("  joint box kept              {:.2f} % of [rho_min, rho_max]^3 within the software limit\n",
                       100.0 * d.joint_box_kept);
  out << "  velocity transmission factors (dimensionless):\n";
  out << fmt::format("    cube                      {} (Proposition 1); numerical search {}\n", range(d.cube),
                     range(check.cube.range));
  out << fmt::format("    joint-bounded workspace   {} (critical points Q, R, S); numerical search {}{}\n",
                     range(d.joint_space), range(check.joint_space.range),
                     std::isfinite(d.joint_sum_limit) ? " with the software limit" : "");
  for (const mechanisms::EncoderOffsetEffect& e : check.encoder_offsets)
    out << fmt::format("    {:<26}{} (numerical search; every slider {:.1f} mm {} than commanded)\n",
                       fmt::format("cube, encoders {:+.1f} mm", e.offset / kMm), range(e.cube.range),
                       std::abs(e.offset) / kMm, e.offset >= 0 ? "further out" : "further in");
}

// The paper's analyses that depend on neither the cube nor the strategy (unit manipulator, L = 1).
void print_paper_analyses(std::ostream& out, const mechanisms::MinimumSwitchPoints& m,
                          const mechanisms::DexterousVolumes& v) {
  out << "Workspace analyses of the paper (unit manipulator L = 1; the same for every cube and strategy):\n";
  out << "  section 5.2, mu_min over the joint box [rho_min, 1]^3 (Fig. 9a):\n";
  out << fmt::format("    S-|R- switch of the formulas   rho_SR = {:.4f}, mu = {:.4f}; numerical search there {:.4f}\n",
                     m.rho_sr, m.mu_sr, m.search_mu_at_rho_sr);
  out << fmt::format("    R-|Q- switch of the formulas   rho_RQ = {:.4f}, mu = {:.4f}; numerical search there {:.4f}\n",
                     m.rho_rq, m.mu_rq, m.search_mu_at_rho_rq);
  out << fmt::format("    true switch to Q-              rho = {:.4f}, mu = {:.4f} (below it the minimum is at no "
                     "critical point: on the edge (rho_min, rho_min, t), or near S- on a face)\n",
                     m.rho_q, m.mu_q);
  out << fmt::format("  Fig. 3: singularity-free workspace V0 = {:.1f} % of the sphere |p| < L (paper: 97.2 %)\n",
                     100.0 * v.singularity_free_of_sphere);
  out << fmt::format("  Table 2, factors bounded by 1/3 and 3: lower {:.3f} V0, two-sided {:.3f} V0, upper {:.3f} V0 "
                     "(paper: 0.84, 0.67, 0.72)\n",
                     v.lower_of_w0, v.two_sided_of_w0, v.upper_of_w0);
}

int run_design(const DesignArgs& a, Context& ctx) {
  auto fail = [&ctx](const Status& s) { return report_failure(ctx, "design orthoglide", s); };
  // Checked here too, to name the option and its unit in the message.
  if (Status s = check_quantity(a.cube_mm, Quantity::kLength, "--cube (the cube edge)", {kMm, "mm"}, Sign::kPositive);
      !s.ok())
    return fail(s);
  if (!(a.mu > 0.0 && a.mu < 1.0))
    return fail(Status::Invalid(
        fmt::format("--mu {}: must lie strictly between 0 and 1 (the factors are bounded to [mu, 1/mu])", a.mu)));
  if (a.strategy && (*a.strategy < 1 || *a.strategy > 3))
    return fail(Status::Invalid(fmt::format("--strategy {}: must be 1, 2 or 3", *a.strategy)));
  // Sizes estimated before anything is allocated or searched.
  using mechanisms::check_grid_points, mechanisms::check_search_points;
  for (const Status& s : {check_grid_points(a.vtk_grid, a.max_points, "--vtk-grid", "--max-points"),
                          check_search_points(a.search_points, a.max_points, "--search-points", "--max-points")})
    if (!s.ok()) return fail(s);
  for (double e : a.encoder_offsets_mm)
    if (!std::isfinite(e))
      return fail(Status::Invalid(fmt::format("--encoder-offsets {} mm: every offset must be a finite number", e)));
  std::vector<double> offsets;
  for (double e : a.encoder_offsets_mm) offsets.push_back(e * kMm);
  const std::vector<int> strategies = a.strategy ? std::vector<int>{*a.strategy} : std::vector<int>{1, 2, 3};
  std::vector<mechanisms::OrthoglideDesign> designs;
  std::vector<mechanisms::OrthoglideDesignCheck> checks;
  for (int s : strategies) {
    auto d = mechanisms::design_orthoglide(s, a.mu, a.cube_mm * kMm);
    if (!d.ok()) return fail(d.status());
    designs.push_back(*d);
    checks.push_back(mechanisms::check_design(*d, a.search_points, offsets));
  }
  Output out(ctx, a.out);
  out.report() << fmt::format(
      "Orthoglide design (Pashkevich, Wenger, Chablat 2005): cube {:.1f} mm, velocity transmission factors in "
      "[{:.3f}, {:.3f}]\n\n",
      a.cube_mm, a.mu, 1.0 / a.mu);
  for (std::size_t i = 0; i < designs.size(); ++i) {
    print_design(out.report(), designs[i], checks[i]);
    if (!a.vtk_dir.empty()) {
      std::vector<std::string> written;
      if (Status st = io::write_orthoglide_workspace_vtk(designs[i], a.vtk_grid, a.vtk_dir, &written, a.max_points);
          !st.ok())
        return fail(st);
      for (const auto& path : written) out.report() << "  wrote " << path << " (lengths in m)\n";
    }
    out.report() << "\n";
  }
  print_paper_analyses(out.report(), mechanisms::unit_minimum_switch_points(a.search_points),
                       mechanisms::unit_dexterous_volumes(1.0 / 3.0, 3.0, kVolumeGrid));
  if (Status st = out.write_json(io::orthoglide_designs_to_json(designs, checks, a.search_points)); !st.ok())
    return fail(st);
  return kExitOk;
}

struct FiveBarDesignArgs {
  std::string r1, r2;  // "lo:hi" or one value, mm
  int steps = 10;
  std::vector<std::string> region;  // "x0:x1", "y0:y1", mm
  std::optional<double> step;       // mm
  std::optional<double> r3_mm;  // default: FiveBarParams' r3
  std::optional<double> min_stiffness;  // N/mm
  std::string mode = "++", assembly = "up", method = "msa";
  double near_singular = mechanisms::MapOptions{}.near_singular_threshold;
  int threads = 0;
  double max_postures = mechanisms::kDefaultMaxDesignPostures;
  std::string vti, png, json;
  bool quiet = false;
};

constexpr const char* kFiveBarCommand = "design fivebar";
constexpr int kPostureSideDefault = 100;  // region points along its longer side without --step

// A sweep's JSON with its timing: on stdout for "-" (nothing else goes there), else into `path`,
// added to `written`.
Status write_sweep_json(nlohmann::json j, const std::string& path, double seconds, std::size_t postures, int threads,
                        Context& ctx, std::vector<std::string>& written) {
  j["timing"] = {{"seconds", seconds},
                 {"postures", postures},
                 {"postures_per_second", static_cast<double>(postures) / seconds},
                 {"threads", threads == 0 ? "all cores" : std::to_string(threads)}};
  if (path == "-") {
    ctx.out << j.dump() << "\n";
    return Status::Ok();
  }
  if (Status s = io::write_json(path, j); !s.ok()) return s;
  written.push_back(path);
  return Status::Ok();
}

std::string mm_range(const mechanisms::MapRange& r) {
  return r.lo == r.hi ? fmt::format("{:g} mm", r.lo / kMm) : fmt::format("{:g}:{:g} mm", r.lo / kMm, r.hi / kMm);
}

int run_five_bar_design(const FiveBarDesignArgs& a, Context& ctx) {
  using namespace mechanisms;
  auto fail = [&](const Status& s) { return report_failure(ctx, kFiveBarCommand, s); };
  FiveBarDesignSweepOptions o;
  if (Status s = parse_five_bar_modes(a.mode, a.assembly, a.method, o.base); !s.ok()) return fail(s);
  for (auto [text, option, range] : {std::tuple{&a.r1, "--r1", &o.r1}, std::tuple{&a.r2, "--r2", &o.r2}}) {
    auto r = parse_range_mm(*text, option);
    if (!r.ok()) return fail(r.status());
    if (!(r->lo > 0.0))
      return fail(Status::Invalid(fmt::format("{} {} mm: link lengths must be positive", option, *text)));
    *range = *r;
  }
  if (a.r3_mm) {
    if (!(*a.r3_mm > 0.0 && std::isfinite(*a.r3_mm)))
      return fail(Status::Invalid(fmt::format("--r3 {:g} mm: the base half-width must be positive", *a.r3_mm)));
    o.base.params.r3 = *a.r3_mm * kMm;
  }
  if (a.steps < 2 || a.steps > 1000)
    return fail(Status::Invalid(fmt::format("--steps {}: designs per link length must lie in [2, 1000]", a.steps)));
  o.steps = a.steps;
  if (a.min_stiffness) {
    if (!(*a.min_stiffness >= 0.0 && std::isfinite(*a.min_stiffness)))
      return fail(Status::Invalid(fmt::format("--min-stiffness {:g} N/mm: give a stiffness >= 0", *a.min_stiffness)));
    o.min_stiffness = *a.min_stiffness / kMm;  // N/mm -> N/m
  }
  if (!(a.near_singular >= 0.0 && a.near_singular <= 1.0))
    return fail(Status::Invalid(fmt::format("--near-singular {:g}: the threshold is in [0, 1]", a.near_singular)));
  o.near_singular_threshold = a.near_singular;
  if (a.threads < 0) return fail(Status::Invalid("--threads must be 0 (all cores) or a positive count"));
  o.threads = a.threads;
  o.max_postures = a.max_postures;

  auto ranges = parse_ranges_mm(a.region, 2, "--region", "x0:x1,y0:y1");
  if (!ranges.ok()) return fail(ranges.status());
  const MapRange& x = (*ranges)[0];
  const MapRange& y = (*ranges)[1];
  double step = 0.0;  // m
  if (a.step) {
    if (!(*a.step > 0.0 && std::isfinite(*a.step)))
      return fail(Status::Invalid(fmt::format("--step {:g} mm: the grid step must be positive", *a.step)));
    step = *a.step * kMm;
  } else {
    step = std::max(x.hi - x.lo, y.hi - y.lo) / (kPostureSideDefault - 1);
    if (!(step > 0.0))
      return fail(Status::Invalid(fmt::format("--region {},{}: a point; give ranges x0:x1,y0:y1 (mm)", a.region[0],
                                              a.region[1])));
  }
  // Counted before anything is allocated.
  const std::size_t max_points = MapOptions{}.max_points;
  const double points = map_axis_points(x, step) * map_axis_points(y, step);
  if (points > static_cast<double>(max_points))
    return fail(Status::Invalid(fmt::format("--step {:g} mm over --region gives {:.3g} points per design, more than {}; "
                                            "use a larger --step",
                                            step / kMm, points, max_points)));
  auto region = make_map_grid({x, y, MapRange{}}, step, max_points);
  if (!region.ok())
    return fail(Status::Invalid(
        fmt::format("--region with --step {:g} mm: {}", step / kMm, region.status().message())));
  o.region = *region;

  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  StatusOr<FiveBarDesignSweep> sweep = Status::Ok();
  {
    Progress progress(ctx.err, "kinestat design fivebar", "postures");
    if (!a.quiet) o.progress = [&progress](std::size_t done, std::size_t total) { progress(done, total); };
    sweep = sweep_five_bar_designs(o);
  }
  if (!sweep.ok()) return fail(sweep.status());
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const std::size_t postures = sweep->results.size() * region->num_points();
  const auto& best = sweep->results[sweep->best];
  const std::string region_text =
      fmt::format("x {}, y {}", mm_range({x.lo, x.lo + (region->dimensions[0] - 1) * step}),
                  mm_range({y.lo, y.lo + (region->dimensions[1] - 1) * step}));
  if (best.reachable == 0 && std::all_of(sweep->results.begin(), sweep->results.end(),
                                         [](const FiveBarDesignResult& r) { return r.reachable == 0; }))
    return fail(Status::Invalid(fmt::format("no design reaches any point of --region ({}) in mode {} {}; nothing "
                                            "written. The region is in the frame of the base (A1 = (-r3, 0), "
                                            "A2 = (r3, 0)); a design reaches about r1 + r2 from its base joints",
                                            region_text, a.mode, a.assembly)));
  const std::string criteria = io::design_sweep_criteria(*sweep);

  std::vector<std::string> written;
  if (!a.vti.empty()) {
    if (Status s = io::write_design_sweep_vti(a.vti, *sweep); !s.ok()) return fail(s);
    written.push_back(a.vti);
  }
  if (!a.png.empty()) {
    if (Status s = io::write_design_sweep_png(a.png, *sweep); !s.ok()) return fail(s);
    written.push_back(a.png);
  }
  const bool json_to_stdout = a.json == "-";
  if (!a.json.empty())
    if (Status s = write_sweep_json(io::design_sweep_to_json(*sweep), a.json, seconds, postures, a.threads, ctx, written);
        !s.ok())
      return fail(s);
  if (json_to_stdout) return kExitOk;

  auto& out = ctx.out;
  const MapGrid& d = sweep->designs;
  out << fmt::format("{} design sweep: {} x {} designs, r1 {}, r2 {}, r3 = {:g} mm\n", sweep->description,
                     d.dimensions[0], d.dimensions[1], mm_range(o.r1), mm_range(o.r2), o.base.params.r3 / kMm);
  out << fmt::format("  region {}, step {:.4g} mm: {} x {} = {} points per design\n", region_text, step / kMm,
                     region->dimensions[0], region->dimensions[1], region->num_points());
  out << fmt::format("  share: the region's points reached with {}\n", criteria);
  const unsigned cores = a.threads > 0 ? static_cast<unsigned>(a.threads) : std::max(1u, std::thread::hardware_concurrency());
  out << fmt::format("  {} postures in {:.2f} s: {:.3g} postures/s on {} thread{}\n", postures, seconds,
                     postures / seconds, cores, cores == 1 ? "" : "s");
  auto line = [&](const FiveBarDesignResult& r) {
    return fmt::format("{:9.4g} {:9.4g} {:8.1f}% {:10.1f}% {:17.1f}% {:17.4g}", r.r1 / kMm, r.r2 / kMm,
                       100.0 * sweep->share(r.stiff), 100.0 * sweep->share(r.reachable),
                       100.0 * sweep->share(r.singularity_free), r.k_t_min_worst * kMm);
  };
  if (best.stiff == 0)
    out << "  no design serves any point of the region with these criteria (see the reachable and singularity-free "
           "shares)\n";
  out << fmt::format("  best design: r1 = {:.4g} mm, r2 = {:.4g} mm: {:.1f}% of the region, k_t_min >= {:.4g} N/mm "
                     "on its singularity-free part\n",
                     best.r1 / kMm, best.r2 / kMm, 100.0 * sweep->share(best.stiff), best.k_t_min_worst * kMm);
  // The leading designs in the order of the choice, so that near-equal alternatives are visible.
  std::vector<std::size_t> order(sweep->results.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return better_design(sweep->results[i], sweep->results[j]); });
  out << fmt::format("  {:>9} {:>9} {:>9} {:>11} {:>18} {:>17}\n", "r1 (mm)", "r2 (mm)", "share", "reachable",
                     "singularity-free", "k_t_min (N/mm) >=");
  for (std::size_t i = 0; i < std::min<std::size_t>(order.size(), 10); ++i)
    out << "  " << line(sweep->results[order[i]]) << "\n";
  for (const std::string& w : written) out << "  wrote " << w << "\n";
  return kExitOk;
}

void add_five_bar_design(CLI::App* design, Context& ctx) {
  auto a = std::make_shared<FiveBarDesignArgs>();
  CLI::App* cmd = design->add_subcommand(
      "fivebar", "five-bar design sweep (docs/maps.md): for every design (r1, r2) of an N x N grid, the share of a "
                 "region of the plane reached singularity-free and stiffer than --min-stiffness; the best design");
  cmd->add_option("--r1", a->r1, "proximal link lengths A_iB_i to sweep, lo:hi in mm (or one value)")->required();
  cmd->add_option("--r2", a->r2, "distal link lengths B_iP to sweep, lo:hi in mm (or one value)")->required();
  cmd->add_option("--steps", a->steps, "designs per swept length, 2 to 1000 (default 10)");
  cmd->add_option("--region", a->region, "the task region x0:x1,y0:y1 in mm (base joints at x = -r3, r3)")
      ->required()
      ->delimiter(',');
  cmd->add_option("--step", a->step, "posture grid step in mm (default: 100 points along the region's longer side)");
  cmd->add_option("--r3", a->r3_mm, "half the base width OA_i in mm (default 100)");
  cmd->add_option("--min-stiffness", a->min_stiffness,
                  "stiffness K in N/mm that k_t_min (the weakest direction) must reach (default: none)");
  cmd->add_option("--mode", a->mode, "working mode ++ (default), +-, -+, -- (write --mode=--)");
  cmd->add_option("--assembly", a->assembly, "assembly mode up (default) or down");
  cmd->add_option("--method", a->method, "stiffness by msa (default) or vjm");
  cmd->add_option("--near-singular", a->near_singular,
                  "points whose singularity measure (0..1) is below this are not usable (default 0.01)");
  cmd->add_option("--threads", a->threads, "threads (default 0: all cores)");
  cmd->add_option("--max-postures", a->max_postures,
                  "refuse sweeps of more designs x region points than this (default 2e8, about 7 min on 2 cores)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--vti", a->vti, "write the design map (x = r1, y = r2 in m) as VTK ImageData (.vti)");
  cmd->add_option("--png", a->png, "write the design map as a PNG (share in %, r1 and r2 in mm)");
  cmd->add_option("--json", a->json, "write every design's shares as JSON ('-': to stdout, nothing else on stdout)");
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->callback([a, &ctx] { ctx.exit_code = run_five_bar_design(*a, ctx); });
}


struct RobotDesignArgs {
  std::string target;               // a robot file
  std::vector<std::string> params;  // "NAME=LO:HI" or "NAME=VALUE", the file's units
  int steps = 3;
  std::vector<std::string> box;     // "lo:hi" per axis, mm
  std::optional<double> step;       // mm
  std::optional<double> min_stiffness;  // N/mm
  std::vector<double> orientation;  // deg
  std::vector<double> load, wrench;  // loaded mode: mm, deg / N, N mm
  double near_singular = mechanisms::MapOptions{}.near_singular_threshold;
  int threads = 0;
  double max_postures = mechanisms::kDefaultMaxRobotDesignPostures;
  std::string json, vti;
  bool quiet = false;
};

constexpr const char* kRobotDesignCommand = "design";
constexpr std::size_t kMaxTableRows = 40;  // more designs: the leading ones by score

// Run by mpirun (Open MPI, MPICH or any PMIx launcher): only then is MPI started, so that a plain
// run does not pay for it.
bool under_mpi_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

// The rank the launcher gave this process (0 when it gave none): without MPI built in, the process
// of rank 0 runs the whole sweep and the others stand aside instead of repeating it.
int launcher_rank() {
  for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
    if (const char* value = std::getenv(v)) return std::atoi(value);
  return 0;
}

// "arm=250:350" or "arm=300", in the file's units (which may be negative: no mm conversion here).
StatusOr<mechanisms::DesignParameter> parse_param(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    return Status::Invalid(fmt::format("--param '{}': write NAME=LO:HI (or NAME=VALUE) in the file's units", text));
  mechanisms::DesignParameter p;
  p.name = text.substr(0, eq);
  const std::string range = text.substr(eq + 1);
  const std::size_t colon = range.find(':', 1);
  const auto lo = parse_number(range.substr(0, colon));
  const auto hi = colon == std::string::npos ? lo : parse_number(range.substr(colon + 1));
  if (!lo || !hi)
    return Status::Invalid(fmt::format("--param {}: '{}' is not a range; write LO:HI or one value (the file's units)",
                                       p.name, range));
  if (*lo > *hi)
    return Status::Invalid(fmt::format("--param {}={} is reversed; write the smaller bound first", p.name, range));
  p.lo = *lo;
  p.hi = *hi;
  return p;
}

std::string measure_text(double m, bool volume) {
  return fmt::format("{:.6g}", m / (volume ? 1e-9 : 1e-6));
}

// What the sweep needs, from the options and the file as written: every --param must name one of its
// parameters; the region is --box or its `workspace:`.
struct RobotDesignSetup {
  mechanisms::RobotDesignSweepOptions options;
  std::string units;  // of the parameters, for the report and the files
  mechanisms::RobotDescription description;
};

StatusOr<RobotDesignSetup> robot_design_setup(const RobotDesignArgs& a) {
  using namespace mechanisms;
  const auto fail = [](Status s) { return s; };
  RobotDesignSetup setup;
  RobotDesignSweepOptions& o = setup.options;
  if (a.target.empty())
    return fail(Status::Invalid("give a robot file (kinestat design ROBOT.yaml --param NAME=LO:HI ...) or a "
                                "subcommand: fivebar, orthoglide"));
  if (a.params.empty())
    return fail(Status::Invalid("--param NAME=LO:HI is required (at least one parameter of the file to sweep)"));
  for (const std::string& text : a.params) {
    auto p = parse_param(text);
    if (!p.ok()) return fail(p.status());
    o.parameters.push_back(*p);
  }
  if (a.steps < 2 || a.steps > 1000)
    return fail(Status::Invalid(fmt::format("--steps {}: designs per parameter must lie in [2, 1000]", a.steps)));
  o.steps = a.steps;
  if (!a.step) return fail(Status::Invalid("--step MM (the posture grid step) is required"));
  if (!(*a.step > 0.0 && std::isfinite(*a.step)))
    return fail(Status::Invalid(fmt::format("--step {:g} mm: the grid step must be positive", *a.step)));
  if (!a.min_stiffness)
    return fail(Status::Invalid("--min-stiffness K (N/mm) is required: the score is the volume where k_t_min >= K"));
  if (!(*a.min_stiffness >= 0.0 && std::isfinite(*a.min_stiffness)))
    return fail(Status::Invalid(fmt::format("--min-stiffness {:g} N/mm: give a stiffness >= 0", *a.min_stiffness)));
  o.min_stiffness = *a.min_stiffness / kMm;  // N/mm -> N/m
  if (!(a.near_singular >= 0.0 && a.near_singular <= 1.0))
    return fail(Status::Invalid(fmt::format("--near-singular {:g}: the threshold is in [0, 1]", a.near_singular)));
  o.near_singular_threshold = a.near_singular;
  if (a.threads < 0) return fail(Status::Invalid("--threads must be 0 (all cores) or a positive count"));
  o.threads = a.threads;
  o.max_postures = a.max_postures;

  // The file as written: its parameters (every --param must name one), units, task and workspace.
  StatusOr<bool> robot = io::is_robot_file(a.target);
  if (!robot.ok()) return fail(robot.status());
  if (!*robot)
    return fail(Status::Invalid(fmt::format("{}: not a robot file (no top-level `robot:`); `kinestat design` takes a "
                                            "robot file (docs/robots.md) or the subcommands fivebar, orthoglide",
                                            a.target)));
  auto file = io::read_robot_params(a.target);
  if (!file.ok()) return fail(file.status());
  for (const DesignParameter& p : o.parameters) {
    const bool known = std::any_of(file->values.begin(), file->values.end(),
                                   [&](const auto& v) { return v.first == p.name; });
    if (!known) {
      std::string names;
      for (const auto& v : file->values) names += (names.empty() ? "" : ", ") + v.first;
      return fail(Status::Invalid(fmt::format("--param {}: no parameter '{}' in {}; its parameters are: {}", p.name,
                                              p.name, a.target, names.empty() ? "none" : names)));
    }
  }
  const std::string units = fmt::format("the units of {} (lengths in {}, forces in {})", a.target, file->length_unit,
                                        file->force_unit);
  auto description = io::read_robot_description(a.target);
  if (!description.ok()) return fail(description.status());
  const RobotDescription& d = *description;
  std::array<MapRange, 3> ranges{};
  if (!a.box.empty()) {
    auto r = parse_ranges_mm(a.box, 3, "--box", "x0:x1,y0:y1,z0:z1");
    if (!r.ok()) return fail(r.status());
    ranges = {(*r)[0], (*r)[1], (*r)[2]};
  } else if (d.workspace) {
    for (int i = 0; i < 3; ++i) ranges[i] = {(*d.workspace)[i].first, (*d.workspace)[i].second};
  } else {
    return fail(Status::Invalid(fmt::format("{}: no `workspace:` in the file; give --box x0:x1,y0:y1,z0:z1 (mm)",
                                            a.target)));
  }
  for (int i = 0; i < 3; ++i) {
    const bool commanded = std::find(d.task.begin(), d.task.end(), static_cast<TaskCoordinate>(i)) != d.task.end();
    if (!commanded && ranges[i].lo != ranges[i].hi)
      return fail(Status::Invalid(fmt::format("{} commands no {}: give a single value for it in --box (e.g. {}0)",
                                              d.name, "xyz"[i], i == 0 ? "" : i == 1 ? "x0:x1," : "x0:x1,y0:y1,")));
  }
  if (Status st = parse_load_options(a.load, a.wrench, o.kernel.displacement, o.kernel.wrench); !st.ok())
    return fail(st);
  if (!a.orientation.empty()) {
    o.kernel.task = VecX::Zero(static_cast<int>(d.task.size()));  // positions: the grid's; angles: these
    if (Status st = set_robot_task_values(d, a.orientation, 3, "--orientation", o.kernel.task); !st.ok())
      return fail(st);
  }
  const std::size_t max_points = MapOptions{}.max_points;
  double points = 1.0;
  for (const MapRange& r : ranges) points *= map_axis_points(r, *a.step * kMm);
  if (points > static_cast<double>(max_points))
    return fail(Status::Invalid(fmt::format("--step {:g} mm over the region gives {:.3g} points per design, more than "
                                            "{}; use a larger --step",
                                            *a.step, points, max_points)));
  auto region = make_map_grid(ranges, *a.step * kMm, max_points);
  if (!region.ok())
    return fail(Status::Invalid(fmt::format("{} with --step {:g} mm: {}", a.box.empty() ? "the file's workspace" : "--box",
                                            *a.step, region.status().message())));
  o.region = *region;
  setup.units = units;
  setup.description = d;
  return setup;
}

int run_robot_design(RobotDesignArgs a, Context& ctx) {
  using namespace mechanisms;
  // Under mpirun every rank runs this; rank 0 alone writes and says why a run failed (the ranks
  // agree on the setup's outcome here and on the sweep's in robot_design_sweep).
  int rank = 0;
  auto fail = [&ctx, &rank](const Status& s) {
    ctx.failure = "kinestat design: " + s.message();
    return rank == 0 ? report_failure(ctx, kRobotDesignCommand, s) : exit_code_for(s);
  };
  if (under_mpi_launcher()) {
    auto group = solver::start_parallel();
    if (!group.ok()) return fail(group.status());
    if (!solver::parallel_running() && launcher_rank() != 0) return kExitOk;  // no MPI: rank 0 runs it all
    rank = group->rank;
    if (rank != 0) a.json.clear(), a.vti.clear(), a.quiet = true;
    if (Status s = solver::same_on_every_rank("the command line", ctx.command_line); !s.ok()) return fail(s);
  }
  // A file one rank cannot read stops every rank (the others would wait for it in the sweep).
  StatusOr<RobotDesignSetup> setup = robot_design_setup(a);
  Status mine = setup.status();
  if (!mine.ok() && rank != 0) mine = Status(mine.code(), fmt::format("MPI rank {}: {}", rank, mine.message()));
  if (Status s = solver::agree_on_status(mine); !s.ok()) return fail(s);
  RobotDesignSweepOptions& o = setup->options;
  const std::string& units = setup->units;
  const RobotDescription& d = setup->description;
  const MapGrid* region = &o.region;
  const std::string& path = a.target;

  // The links' `fea:` springs are computed for the first design and reused (they take no parameters).
  std::map<int, Mat6> fea_springs;
  const RobotDesignFactory factory = [&](const std::vector<std::pair<std::string, double>>& values) {
    return load_robot_model(ctx, "design", path, a.quiet, values, &fea_springs);
  };
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  StatusOr<RobotDesignSweep> sweep = Status::Ok();
  {
    Progress progress(ctx.err, "kinestat design", "postures");
    if (!a.quiet) o.progress = [&progress](std::size_t done, std::size_t total) { progress(done, total); };
    sweep = robot_design_sweep(factory, o);
  }
  if (!sweep.ok()) return fail(sweep.status());
  if (rank != 0) return kExitOk;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const RobotDesignSweep& s = *sweep;
  const std::size_t postures = s.results.size() * region->num_points();

  std::vector<std::string> written;
  if (!a.vti.empty()) {
    if (Status st = io::write_robot_design_sweep_vti(a.vti, s, units); !st.ok()) return fail(st);
    written.push_back(a.vti);
  }
  const bool json_to_stdout = a.json == "-";
  if (!a.json.empty())
    if (Status st = write_sweep_json(io::robot_design_sweep_to_json(s, a.target, units), a.json, seconds, postures,
                                     a.threads, ctx, written);
        !st.ok())
      return fail(st);
  if (json_to_stdout) return kExitOk;

  auto& out = ctx.out;
  const bool volume = s.volume();
  const char* unit = volume ? "mm^3" : "mm^2";
  std::string swept;
  for (std::size_t p = 0; p < s.parameters.size(); ++p)
    swept += fmt::format("{}{} {:g}:{:g} ({})", p ? ", " : "", s.parameters[p].name, s.parameters[p].lo,
                         s.parameters[p].hi, s.dimensions[p]);
  out << fmt::format("{}: design sweep of {} designs: {}\n", s.description.empty() ? d.name : s.description,
                     s.results.size(), swept);
  out << fmt::format("  parameters in {}\n", units);
  const MapGrid& g = s.region;
  out << fmt::format("  region x {:g}:{:g}, y {:g}:{:g}, z {:g}:{:g} mm, step {:g} mm: {} x {} x {} = {} points per "
                     "design\n",
                     g.origin.x() / kMm, (g.origin.x() + (g.dimensions[0] - 1) * g.spacing.x()) / kMm,
                     g.origin.y() / kMm, (g.origin.y() + (g.dimensions[1] - 1) * g.spacing.y()) / kMm,
                     g.origin.z() / kMm, (g.origin.z() + (g.dimensions[2] - 1) * g.spacing.z()) / kMm, *a.step,
                     g.dimensions[0], g.dimensions[1], g.dimensions[2], g.num_points());
  out << fmt::format("  score: the {} ({}) where k_t_min >= {:g} N/mm (the stiff {}); best: the largest\n",
                     volume ? "volume" : "area", unit, *a.min_stiffness, volume ? "volume" : "area");
  std::size_t failed = 0;
  for (const RobotDesignResult& r : s.results) failed += r.status.ok() ? 0 : 1;
  out << fmt::format("  {} postures in {:.2f} s ({:.3g} postures/s){}{}\n", postures, seconds, postures / seconds,
                     s.ranks > 1 ? fmt::format(" on {} MPI ranks", s.ranks) : "",
                     failed ? fmt::format("; {} design{} failed", failed, failed == 1 ? "" : "s") : "");
  const RobotDesignResult& best = s.results[s.best];
  std::string best_values;
  for (std::size_t p = 0; p < s.parameters.size(); ++p)
    best_values += fmt::format("{}{} = {:g}", p ? ", " : "", s.parameters[p].name, best.values[p]);
  out << fmt::format("  best design: {}: stiff {} {} of {} {} reachable\n", best_values,
                     measure_text(best.stiff_measure, volume), unit, measure_text(best.reachable_measure, volume),
                     unit);
  if (best.stiff_points == 0)
    out << "  no design has a point with k_t_min >= K in the region (see the reachable measures)\n";
  // The table: every design in grid order, or the leading ones by score when there are many.
  std::vector<std::size_t> order(s.results.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (order.size() > kMaxTableRows) {
    std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
      const auto key = [&](std::size_t k) { return s.results[k].status.ok() ? s.results[k].stiff_points + 1 : 0; };
      return key(i) > key(j);
    });
    order.resize(kMaxTableRows);
    out << fmt::format("  the {} leading designs of {}:\n", kMaxTableRows, s.results.size());
  }
  std::string header = "  ";
  for (const DesignParameter& p : s.parameters) header += fmt::format("{:>12} ", p.name);
  header += fmt::format("{:>16} {:>16} {:>7} {:>14}  {}\n", fmt::format("stiff ({})", unit),
                        fmt::format("reachable ({})", unit), "stiff %", "k_t_min (N/mm)", "status");
  out << header;
  for (std::size_t k : order) {
    const RobotDesignResult& r = s.results[k];
    std::string line = "  ";
    for (double v : r.values) line += fmt::format("{:>12g} ", v);
    if (r.status.ok()) {
      const double share = r.reachable_points > 0 ? 100.0 * r.stiff_points / r.reachable_points : 0.0;
      line += fmt::format("{:>16} {:>16} {:>7.1f} {:>14.4g}  ok{}", measure_text(r.stiff_measure, volume),
                          measure_text(r.reachable_measure, volume), share, r.k_t_min_worst * kMm,
                          k == s.best ? " (best)" : "");
    } else {
      line += fmt::format("{:>16} {:>16} {:>7} {:>14}  failed: {}", "-", "-", "-", "-", r.status.message());
    }
    out << line << "\n";
  }
  for (const std::string& w : written) out << "  wrote " << w << "\n";
  return kExitOk;
}

}  // namespace

void register_design_command(CLI::App& app, Context& ctx) {
  CLI::App* design = app.add_subcommand(
      "design", "design sweep of a robot file (ROBOT.yaml --param NAME=LO:HI ...: the best design by the volume "
                "stiffer than --min-stiffness; docs/maps.md), or the subcommands fivebar and orthoglide");
  design->require_subcommand(0, 1);
  // A robot file: the options below belong to it; `design fivebar` and `design orthoglide` have their own.
  auto robot = std::make_shared<RobotDesignArgs>();
  design->add_option("robot", robot->target, "a robot file (YAML with `robot:`, docs/robots.md; models/robots/)");
  design->add_option("--param", robot->params,
                     "NAME=LO:HI (or NAME=VALUE): a parameter of the file to sweep, in the file's units; repeat for "
                     "more");
  design->add_option("--steps", robot->steps, "designs per swept parameter, 2 to 1000 (default 3)");
  design->add_option("--box", robot->box,
                     "the region x0:x1,y0:y1,z0:z1 in mm (default: the file's workspace:)")
      ->delimiter(',');
  design->add_option("--step", robot->step, "posture grid step in mm (required)");
  design->add_option("--min-stiffness", robot->min_stiffness,
                     "stiffness K in N/mm: a design's score is the volume (area) where k_t_min >= K (required)");
  design->add_option("--orientation", robot->orientation,
                     "the tool's orientation rx,ry,rz in deg for the task's angles (default: home's, 0)")
      ->delimiter(',');
  CLI::Option* load = design->add_option("--load", robot->load,
                                         "prescribed tool displacement dx,dy,dz (mm), rx,ry,rz (deg): the loaded mode")
                          ->delimiter(',');
  design->add_option("--wrench", robot->wrench,
                     "external wrench Fx,Fy,Fz (N), Mx,My,Mz (N mm) at the tool point: the loaded mode")
      ->delimiter(',')
      ->excludes(load);
  design->add_option("--near-singular", robot->near_singular,
                     "points whose singularity measure (0..1) is below this are near-singular (default 0.01)");
  design->add_option("--threads", robot->threads, "threads per process (default 0: all cores)");
  design->add_option("--max-postures", robot->max_postures,
                     "refuse sweeps of more designs x region points than this (default 2e6, about 8 min on 2 cores)")
      ->check(CLI::PositiveNumber);
  design->add_option("--json", robot->json, "write every design and the best as JSON ('-': to stdout, nothing else)");
  design->add_option("--vti", robot->vti, "write the design map (one to three parameters) as VTK ImageData (.vti)");
  design->add_flag("--quiet", robot->quiet, "no progress on stderr");
  design->callback([design, robot, &ctx] {
    if (!design->get_subcommands().empty()) return;  // fivebar or orthoglide ran
    ctx.exit_code = run_robot_design(*robot, ctx);
  });
  auto args = std::make_shared<DesignArgs>();
  CLI::App* cmd = design->add_subcommand(
      "orthoglide", "Orthoglide design strategies of Pashkevich, Wenger, Chablat 2005 (Table 3): link length, joint "
                    "limits and cube location for a cubic workspace and transmission factors in [mu, 1/mu]");
  cmd->add_option("--cube", args->cube_mm, "edge of the cubic workspace, in mm (or with a unit: 0.2m, 20cm)")
      ->required()
      ->transform(CLI::AsNumberWithUnit(std::map<std::string, double>{{"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}}));
  cmd->add_option("--mu", args->mu, "lower bound mu of the velocity transmission factors (dimensionless), 0 < mu < 1 (upper: 1/mu)")
      ->required();
  cmd->add_option("--strategy", args->strategy, "design strategy 1, 2 or 3 (default: all three)");
  CLI::Option* vtk = cmd->add_option("--vtk", args->vtk_dir,
                                     "write the joint-bounded workspace and the cube as .vtu files (SI units) to DIR");
  cmd->add_option("--vtk-grid", args->vtk_grid, "joint grid points per axis in the VTK workspace (default 21)")
      ->needs(vtk);
  cmd->add_option("--search-points", args->search_points,
                  "points per face edge of the numerical check of the transmission factors (default 41)");
  cmd->add_option("--encoder-offsets", args->encoder_offsets_mm,
                  "encoder offsets, in mm, whose effect on the cube's factors is reported: every slider that much "
                  "further out than commanded (default 5,10)")
      ->delimiter(',');
  cmd->add_option("--max-points", args->max_points,
                  "refuse --vtk-grid N (N^3 points) or --search-points N (~7 N^2 + N^3/64 points) above this")
      ->capture_default_str();
  add_output_options(*cmd, args->out, "kinestat-orthoglide-design");
  cmd->callback([args, &ctx] { ctx.exit_code = run_design(*args, ctx); });
  add_five_bar_design(design, ctx);
}

}  // namespace kinestat::cli
