// kinestat design ROBOT.yaml --param NAME=LO:HI ... --steps N [--box X0:X1,Y0:Y1,Z0:Z1] --step MM [--load D | --wrench
// W]
//                            --min-stiffness K [--json FILE|-] [--vti FILE] [--quiet]
// Design sweep of a robot file (mechanisms/robot_design_sweep.hpp): every design of the grid of the
// named parameters (the file re-read with their values, io::read_robot_model), its map of one
// region, its volume (area) with k_t_min >= K; the best design. Under mpirun the designs are split
// across the ranks; rank 0 writes.
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
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/command_output.hpp"
#include "cli/grid_options.hpp"
#include "kinestat/cli/app.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/robot_design_output.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/io/workspace_vtk.hpp"
#include "kinestat/mechanisms/robot_design_sweep.hpp"
#include "kinestat/solver/parallel.hpp"

namespace kinestat::cli {

Status write_sweep_json(Output& out, const OutputOptions& options, const std::function<nlohmann::json()>& make,
                        double seconds, std::size_t postures, int threads, std::vector<std::string>& written) {
  if (!out.json_wanted()) return Status::Ok();
  nlohmann::json j = make();
  j["timing"] = {{"seconds", seconds},
                 {"postures", postures},
                 {"postures_per_second", static_cast<double>(postures) / seconds},
                 {"threads", threads == 0 ? "all cores" : std::to_string(threads)}};
  if (Status s = out.write_json(j); !s.ok()) return s;
  if (options.json != "-") written.push_back(options.json);
  return Status::Ok();
}

namespace {

using units::kMm;  // lengths are printed in mm

struct RobotDesignArgs {
  std::string target;               // a robot file
  std::vector<std::string> params;  // "NAME=LO:HI" or "NAME=VALUE", the file's units
  int steps = 3;
  std::vector<std::string> box;         // "lo:hi" per axis, mm
  std::optional<double> step;           // mm
  std::optional<double> min_stiffness;  // N/mm
  std::vector<double> orientation;      // deg
  std::vector<double> load, wrench;     // loaded mode: mm, deg / N, N mm
  double near_singular = mechanisms::MapOptions{}.near_singular_threshold;
  int threads = 0;
  double max_postures = mechanisms::kDefaultMaxRobotDesignPostures;
  std::string vti;
  OutputOptions out;  // --json FILE|-, --quiet
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
    return Status::Invalid(
        fmt::format("--param {}: '{}' is not a range; write LO:HI or one value (the file's units)", p.name, range));
  if (*lo > *hi)
    return Status::Invalid(fmt::format("--param {}={} is reversed; write the smaller bound first", p.name, range));
  p.lo = *lo;
  p.hi = *hi;
  return p;
}

std::string measure_text(double m, bool volume) { return fmt::format("{:.6g}", m / (volume ? 1e-9 : 1e-6)); }

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
    return fail(
        Status::Invalid("give a robot file (kinestat design ROBOT.yaml --param NAME=LO:HI ...) or a "
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
  if (Status st = set_sweep_options(a.min_stiffness, a.near_singular, a.threads, a.max_postures, o); !st.ok())
    return fail(st);

  // The file as written: its parameters (every --param must name one), units, task and workspace.
  StatusOr<bool> robot = io::is_robot_file(a.target);
  if (!robot.ok()) return fail(robot.status());
  if (!*robot)
    return fail(
        Status::Invalid(fmt::format("{}: not a robot file (no top-level `robot:`); `kinestat design` takes a "
                                    "robot file (docs/robots.md) or the subcommands fivebar, orthoglide",
                                    a.target)));
  auto file = io::read_robot_params(a.target);
  if (!file.ok()) return fail(file.status());
  for (const DesignParameter& p : o.parameters) {
    const bool known =
        std::any_of(file->values.begin(), file->values.end(), [&](const auto& v) { return v.first == p.name; });
    if (!known) {
      std::string names;
      for (const auto& v : file->values) names += (names.empty() ? "" : ", ") + v.first;
      return fail(Status::Invalid(fmt::format("--param {}: no parameter '{}' in {}; its parameters are: {}", p.name,
                                              p.name, a.target, names.empty() ? "none" : names)));
    }
  }
  const std::string units =
      fmt::format("the units of {} (lengths in {}, forces in {})", a.target, file->length_unit, file->force_unit);
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
    return fail(
        Status::Invalid(fmt::format("{}: no `workspace:` in the file; give --box x0:x1,y0:y1,z0:z1 (mm)", a.target)));
  }
  if (auto axes = robot_grid_axes(d, ranges, false, "--box"); !axes.ok()) return fail(axes.status());
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
    return fail(
        Status::Invalid(fmt::format("--step {:g} mm over the region gives {:.3g} points per design, more than "
                                    "{}; use a larger --step",
                                    *a.step, points, max_points)));
  auto region = make_map_grid(ranges, *a.step * kMm, max_points);
  if (!region.ok())
    return fail(
        Status::Invalid(fmt::format("{} with --step {:g} mm: {}", a.box.empty() ? "the file's workspace" : "--box",
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
    if (rank != 0) a.out.json.clear(), a.vti.clear(), a.out.quiet = true;
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
    return load_robot_model(ctx, "design", path, a.out.quiet, values, &fea_springs);
  };
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  StatusOr<RobotDesignSweep> sweep = Status::Ok();
  {
    Progress progress(ctx.err, "kinestat design", "postures");
    if (!a.out.quiet) o.progress = [&progress](std::size_t done, std::size_t total) { progress(done, total); };
    sweep = robot_design_sweep(factory, o);
  }
  if (!sweep.ok()) return fail(sweep.status());
  if (rank != 0) return kExitOk;
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const RobotDesignSweep& s = *sweep;
  const std::size_t postures = s.results.size() * region->num_points();
  // No design with a point that has a stiffness: a "best" of them would be a NaN score.
  if (std::none_of(s.results.begin(), s.results.end(),
                   [](const RobotDesignResult& r) { return r.status.ok() && std::isfinite(r.k_t_min_worst); })) {
    const bool reached = std::any_of(s.results.begin(), s.results.end(),
                                     [](const RobotDesignResult& r) { return r.reachable_points > 0; });
    if (!reached)
      return fail(
          Status::Invalid(fmt::format("none of the {} designs reaches a point of the region; nothing written. "
                                      "Choose a region inside the workspace (--box)",
                                      s.results.size())));
    return fail(Status::Singular(
        fmt::format("no design has a point with a stiffness in the region: every reachable posture of the {} designs "
                    "is singular or failed; nothing written. `kinestat map` of one design says why",
                    s.results.size())));
  }

  std::vector<std::string> written;
  if (!a.vti.empty()) {
    if (Status st = io::write_robot_design_sweep_vti(a.vti, s, units); !st.ok()) return fail(st);
    written.push_back(a.vti);
  }
  Output output(ctx, a.out);
  if (Status st = write_sweep_json(
          output, a.out, [&] { return io::robot_design_sweep_to_json(s, a.target, units); }, seconds, postures,
          a.threads, written);
      !st.ok())
    return fail(st);

  std::ostream& out = output.report();
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
  out << fmt::format(
      "  region x {:g}:{:g}, y {:g}:{:g}, z {:g}:{:g} mm, step {:g} mm: {} x {} x {} = {} points per "
      "design\n",
      g.origin.x() / kMm, (g.origin.x() + (g.dimensions[0] - 1) * g.spacing.x()) / kMm, g.origin.y() / kMm,
      (g.origin.y() + (g.dimensions[1] - 1) * g.spacing.y()) / kMm, g.origin.z() / kMm,
      (g.origin.z() + (g.dimensions[2] - 1) * g.spacing.z()) / kMm, *a.step, g.dimensions[0], g.dimensions[1],
      g.dimensions[2], g.num_points());
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
      "design",
      "design sweep of a robot file (ROBOT.yaml --param NAME=LO:HI ...: the best design by the volume "
      "stiffer than --min-stiffness; docs/maps.md), or the subcommands fivebar and orthoglide");
  design->require_subcommand(0, 1);
  // A robot file: the options below belong to it; `design fivebar` and `design orthoglide` have their own.
  auto robot = std::make_shared<RobotDesignArgs>();
  design->add_option("robot", robot->target, "a robot file (YAML with `robot:`, docs/robots.md; models/robots/)");
  design->add_option("--param", robot->params,
                     "NAME=LO:HI (or NAME=VALUE): a parameter of the file to sweep, in the file's units; repeat for "
                     "more");
  design->add_option("--steps", robot->steps, "designs per swept parameter, 2 to 1000 (default 3)");
  design->add_option("--box", robot->box, "the region x0:x1,y0:y1,z0:z1 in mm (default: the file's workspace:)")
      ->delimiter(',');
  design->add_option("--step", robot->step, "posture grid step in mm (required)");
  design->add_option("--min-stiffness", robot->min_stiffness,
                     "stiffness K in N/mm: a design's score is the volume (area) where k_t_min >= K (required)");
  design
      ->add_option("--orientation", robot->orientation,
                   "the tool's orientation rx,ry,rz in deg for the task's angles (default: home's, 0)")
      ->delimiter(',');
  CLI::Option* load = design
                          ->add_option("--load", robot->load,
                                       "prescribed tool displacement dx,dy,dz (mm), rx,ry,rz (deg): the loaded mode")
                          ->delimiter(',');
  design
      ->add_option("--wrench", robot->wrench,
                   "external wrench Fx,Fy,Fz (N), Mx,My,Mz (N mm) at the tool point: the loaded mode")
      ->delimiter(',')
      ->excludes(load);
  design->add_option("--near-singular", robot->near_singular,
                     "points whose singularity measure (0..1) is below this are near-singular (default 0.01)");
  design->add_option("--threads", robot->threads, "threads per process (default 0: all cores)");
  design
      ->add_option("--max-postures", robot->max_postures,
                   "refuse sweeps of more designs x region points than this (default 1.5e7, about 8 min on 2 cores)")
      ->check(positive_number());
  design->add_option("--vti", robot->vti, "write the design map (one to three parameters) as VTK ImageData (.vti)");
  add_output_options(*design, robot->out, "kinestat-robot-design-sweep", "docs/maps.md");
  design->callback([design, robot, &ctx] {
    if (!design->get_subcommands().empty()) return;  // fivebar or orthoglide ran
    ctx.exit_code = run_robot_design(*robot, ctx);
  });
  add_orthoglide_design(design, ctx);
  add_five_bar_design(design, ctx);
}

}  // namespace kinestat::cli
