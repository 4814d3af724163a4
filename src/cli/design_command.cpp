// kinestat design orthoglide --cube C --mu MU [--strategy 1|2|3] [--vtk DIR] [--encoder-offsets E1,E2]
//                            [--json FILE|-]
// Geometric synthesis of the Orthoglide (Pashkevich, Wenger, Chablat 2005, Table 3): link length,
// joint limits and cube location for a cube of edge C and transmission factors in [MU, 1/MU]; the
// paper's other analyses (section 5.2 switch points, Fig. 3 and Table 2 volumes, encoder offsets).
//
// kinestat design fivebar --r1 A:B --r2 C:D --steps N --region X0:X1,Y0:Y1 [--min-stiffness K] ...
// Design sweep of the five-bar (mechanisms/five_bar_design_sweep.hpp): the share of a region that
// each design (r1, r2) reaches singularity-free and stiffer than K; the best design; VTI, PNG, JSON.
#include <algorithm>
#include <chrono>
#include <cmath>
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
#include "kinestat/io/workspace_map_png.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/workspace_vtk.hpp"
#include "kinestat/mechanisms/five_bar_design_sweep.hpp"
#include "kinestat/mechanisms/orthoglide_design.hpp"

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
// paper's own ray method, tests/mechanisms/test_orthoglide_design.cpp).
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
  if (!a.json.empty()) {
    nlohmann::json j = io::design_sweep_to_json(*sweep);
    j["timing"] = {{"seconds", seconds},
                   {"postures", postures},
                   {"postures_per_second", postures / seconds},
                   {"threads", a.threads == 0 ? "all cores" : std::to_string(a.threads)}};
    if (json_to_stdout) {
      ctx.out << j.dump() << "\n";
    } else {
      if (Status s = io::write_json(a.json, j); !s.ok()) return fail(s);
      written.push_back(a.json);
    }
  }
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

}  // namespace

void register_design_command(CLI::App& app, Context& ctx) {
  CLI::App* design = app.add_subcommand("design", "geometric synthesis of a mechanism");
  design->require_subcommand(1);
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
