// kinestat design fivebar --r1 A:B --r2 C:D --steps N --region X0:X1,Y0:Y1 [--min-stiffness K] ...
// Design sweep of the five-bar (mechanisms/five_bar_design_sweep.hpp): the share of a region that
// each design (r1, r2) reaches singularity-free and stiffer than K; the best design; VTI, PNG, JSON.
#include "cli/design_commands.hpp"

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
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/command_output.hpp"
#include "cli/grid_options.hpp"
#include "kinestat/cli/app.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/threads.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/io/five_bar_design_output.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/workspace_map_png.hpp"
#include "kinestat/io/workspace_vtk.hpp"
#include "kinestat/mechanisms/five_bar_design_sweep.hpp"

namespace kinestat::cli {
namespace {

using units::kMm;  // lengths are printed in mm

struct FiveBarDesignArgs {
  std::string r1, r2;  // "lo:hi" or one value, mm
  int steps = 10;
  std::vector<std::string> region;      // "x0:x1", "y0:y1", mm
  std::optional<double> step;           // mm
  std::optional<double> r3_mm;          // default: FiveBarParams' r3
  std::optional<double> min_stiffness;  // N/mm
  std::string mode = "++", assembly = "up", method = "msa";
  double near_singular = mechanisms::MapOptions{}.near_singular_threshold;
  int threads = 0;
  double max_postures = mechanisms::kDefaultMaxDesignPostures;
  std::string vti, png;
  OutputOptions out;  // --json FILE|-, --quiet
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
  if (Status st = set_sweep_options(a.min_stiffness, a.near_singular, a.threads, a.max_postures, o); !st.ok())
    return fail(st);

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
      return fail(Status::Invalid(
          fmt::format("--region {},{}: a point; give ranges x0:x1,y0:y1 (mm)", a.region[0], a.region[1])));
  }
  // Counted before anything is allocated.
  const std::size_t max_points = MapOptions{}.max_points;
  const double points = map_axis_points(x, step) * map_axis_points(y, step);
  if (points > static_cast<double>(max_points))
    return fail(
        Status::Invalid(fmt::format("--step {:g} mm over --region gives {:.3g} points per design, more than {}; "
                                    "use a larger --step",
                                    step / kMm, points, max_points)));
  auto region = make_map_grid({x, y, MapRange{}}, step, max_points);
  if (!region.ok())
    return fail(
        Status::Invalid(fmt::format("--region with --step {:g} mm: {}", step / kMm, region.status().message())));
  o.region = *region;

  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  StatusOr<FiveBarDesignSweep> sweep = Status::Ok();
  {
    Progress progress(ctx.err, "kinestat design fivebar", "postures");
    if (!a.out.quiet) o.progress = [&progress](std::size_t done, std::size_t total) { progress(done, total); };
    sweep = sweep_five_bar_designs(o);
  }
  if (!sweep.ok()) return fail(sweep.status());
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const std::size_t postures = sweep->results.size() * region->num_points();
  const auto& best = sweep->results[sweep->best];
  const std::string region_text = fmt::format("x {}, y {}", mm_range({x.lo, x.lo + (region->dimensions[0] - 1) * step}),
                                              mm_range({y.lo, y.lo + (region->dimensions[1] - 1) * step}));
  if (best.reachable == 0 && std::all_of(sweep->results.begin(), sweep->results.end(),
                                         [](const FiveBarDesignResult& r) { return r.reachable == 0; }))
    return fail(
        Status::Invalid(fmt::format("no design reaches any point of --region ({}) in mode {} {}; nothing "
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
  Output output(ctx, a.out);
  if (Status s = write_sweep_json(
          output, a.out, [&] { return io::design_sweep_to_json(*sweep); }, seconds, postures, a.threads, written);
      !s.ok())
    return fail(s);

  std::ostream& out = output.report();
  const MapGrid& d = sweep->designs;
  out << fmt::format("{} design sweep: {} x {} designs, r1 {}, r2 {}, r3 = {:g} mm\n", sweep->description,
                     d.dimensions[0], d.dimensions[1], mm_range(o.r1), mm_range(o.r2), o.base.params.r3 / kMm);
  out << fmt::format("  region {}, step {:.4g} mm: {} x {} = {} points per design\n", region_text, step / kMm,
                     region->dimensions[0], region->dimensions[1], region->num_points());
  out << fmt::format("  share: the region's points reached with {}\n", criteria);
  const unsigned cores = a.threads > 0 ? static_cast<unsigned>(a.threads) : static_cast<unsigned>(available_cpus());
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
  out << fmt::format(
      "  best design: r1 = {:.4g} mm, r2 = {:.4g} mm: {:.1f}% of the region, k_t_min >= {:.4g} N/mm "
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

}  // namespace

void add_five_bar_design(CLI::App* design, Context& ctx) {
  auto a = std::make_shared<FiveBarDesignArgs>();
  CLI::App* cmd = design->add_subcommand(
      "fivebar",
      "five-bar design sweep (docs/maps.md): for every design (r1, r2) of an N x N grid, the share of a "
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
      ->check(positive_number());
  cmd->add_option("--vti", a->vti, "write the design map (x = r1, y = r2 in m) as VTK ImageData (.vti)");
  cmd->add_option("--png", a->png, "write the design map as a PNG (share in %, r1 and r2 in mm)");
  add_output_options(*cmd, a->out, "kinestat-five-bar-design-sweep", "docs/maps.md");
  cmd->callback([a, &ctx] { ctx.exit_code = run_five_bar_design(*a, ctx); });
}

}  // namespace kinestat::cli
