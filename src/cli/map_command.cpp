// kinestat map fivebar [--mode ++] [--assembly up] [--method msa] [--region x0:x1,y0:y1] [--step MM] [--load W]
// kinestat map MODEL.yaml --box x0:x1,y0:y1,z0:z1 --step MM [--load D | --wrench W]
// kinestat map ROBOT.yaml --step MM [--box ..] [--orientation rx,ry,rz] [--method vjm|msa] [--load D | --wrench W]
// A workspace stiffness map (mechanisms/workspace_map.hpp; docs/maps.md): every point of a grid,
// written as VTI (ParaView), JSON and PNG, with a short summary on stdout.
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/command_output.hpp"
#include "cli/grid_options.hpp"
#include "kinestat/cli/app.hpp"
#include "kinestat/core/threads.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/io/map_json.hpp"
#include "kinestat/io/map_vti.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/io/workspace_map_png.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/five_bar_loci.hpp"
#include "kinestat/mechanisms/orthoglide_kernel.hpp"
#include "kinestat/mechanisms/robot_design_sweep.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::cli {
namespace {

using namespace kinestat::mechanisms;

using units::kDeg;
using units::kMm;
constexpr const char* kCommand = "map";

struct MapArgs {
  std::string target;  // "fivebar" or a VJM model file
  std::string mode = "++", assembly = "up", method = "msa";
  std::vector<std::string> region, box;  // "lo:hi" per axis, mm
  std::optional<double> step;            // mm
  std::vector<double> load, wrench, orientation, position;
  std::vector<std::string> angles;      // "lo:hi" per rotation, deg
  std::optional<double> angle_step;     // deg
  std::optional<double> min_stiffness;  // N/mm
  double near_singular = MapOptions{}.near_singular_threshold;
  std::size_t max_points = MapOptions{}.max_points;
  int threads = 0;
  std::string vti, png, field = "k_t_min";
  OutputOptions out;  // --json, --quiet
  // Options given on the command line, to refuse those that do not apply to the target.
  CLI::Option *mode_opt = nullptr, *assembly_opt = nullptr, *method_opt = nullptr, *region_opt = nullptr,
              *box_opt = nullptr, *wrench_opt = nullptr, *orientation_opt = nullptr, *angles_opt = nullptr,
              *position_opt = nullptr, *angle_step_opt = nullptr;
};

// What the target needs before the grid: the kernel, the ranges, the curves, words for messages.
struct MapSetup {
  std::unique_ptr<PostureKernel> kernel;
  std::array<MapRange, 3> ranges{};  // m, or rad for an orientation map
  bool angular = false;              // an orientation map: axes rx, ry, rz, --angle-step in deg
  std::string range_option;          // the option, or the robot file's `workspace:`, that gave the ranges
  bool with_load = false;
  bool robot_file = false;  // the generic kernel: its rate for the estimated time
  std::vector<MapCurve> curves;
  std::string workspace_hint;  // where the reachable region is, for an empty map
};

Status refuse_if_given(const CLI::Option* o, const std::string& why) {
  if (o != nullptr && o->count() > 0) return Status::Invalid(fmt::format("{} {}", o->get_name(), why));
  return Status::Ok();
}

StatusOr<MapSetup> five_bar_setup(const MapArgs& a) {
  for (const CLI::Option* o :
       {a.box_opt, a.wrench_opt, a.orientation_opt, a.angles_opt, a.position_opt, a.angle_step_opt})
    if (Status s = refuse_if_given(o,
                                   "applies to model files; the five-bar takes --region x0:x1,y0:y1 (mm) and "
                                   "--load Fx,Fy,Fz,Mx,My,Mz (N, N mm)");
        !s.ok())
      return s;
  FiveBarKernelOptions o;
  if (Status st = parse_five_bar_modes(a.mode, a.assembly, a.method, o); !st.ok()) return st;
  MapSetup s;
  if (!a.load.empty()) {
    auto w = parse_wrench_option(a.load, "--load");
    if (!w.ok()) return w.status();
    o.load = *w;
    s.with_load = true;
  }
  auto box = five_bar_workspace_box(o.params, o.mode, o.assembly);
  if (!box.ok()) return box.status();
  s.workspace_hint = fmt::format("the workspace of this mode spans x {:.1f}:{:.1f}, y {:.1f}:{:.1f} mm",
                                 box->min.x() / kMm, box->max.x() / kMm, box->min.y() / kMm, box->max.y() / kMm);
  s.range_option = "--region";
  if (!a.region.empty()) {
    auto r = parse_ranges_mm(a.region, 2, "--region", "x0:x1,y0:y1");
    if (!r.ok()) return r.status();
    s.ranges = {(*r)[0], (*r)[1], MapRange{}};
  } else {
    // The workspace's bounding box widened to multiples of the step: a symmetric robot gets a
    // symmetric grid, and the grid lines fall on round numbers.
    const double step = *a.step;
    for (int i = 0; i < 2; ++i)
      s.ranges[i] = {std::floor(box->min(i) / kMm / step + 1e-9) * step * kMm,
                     std::ceil(box->max(i) / kMm / step - 1e-9) * step * kMm};
  }
  if (Status st = validate(o); !st.ok()) return st;
  s.curves = five_bar_singular_loci(o.params, o.mode, o.assembly);
  s.kernel = make_five_bar_kernel(o);
  return s;
}

StatusOr<MapSetup> model_setup(const MapArgs& a) {
  for (const CLI::Option* o : {a.mode_opt, a.assembly_opt, a.method_opt, a.region_opt, a.orientation_opt, a.angles_opt,
                               a.position_opt, a.angle_step_opt})
    if (Status s = refuse_if_given(o,
                                   "applies to `kinestat map fivebar` only; a model file takes --box, --step, "
                                   "--load or --wrench");
        !s.ok())
      return s;
  if (a.box.empty())
    return Status::Invalid(
        fmt::format("{} is no robot file (it has no `robot:` key): as a model file (docs/maps.md) it needs "
                    "--box x0:x1,y0:y1,z0:z1 (mm)",
                    a.target));
  if (!a.step) return Status::Invalid("--step MM is required with a model file");
  MapSetup s;
  s.range_option = "--box";
  auto r = parse_ranges_mm(a.box, 3, "--box", "x0:x1,y0:y1,z0:z1");
  if (!r.ok()) return r.status();
  s.ranges = {(*r)[0], (*r)[1], (*r)[2]};
  OrthoglideKernelOptions o;
  if (Status st = parse_load_options(a.load, a.wrench, o.displacement, o.wrench); !st.ok()) return st;
  s.with_load = o.displacement || o.wrench;
  // Read after the options, so that a bad option is reported first (reading meshes nothing: `fea:`
  // springs are computed by io::resolve_fea_springs, which the Orthoglide kernel does not call).
  auto model = io::read_vjm_model_yaml(a.target);
  if (!model.ok()) return model.status();
  if (!model->orthoglide)
    return Status::Invalid(
        fmt::format("{}: a `chains:` model fixes one posture, so it has no workspace to map; use "
                    "a model with `mechanism: orthoglide` (models/orthoglide_puu.yaml)",
                    a.target));
  o.model = *model->orthoglide;
  o.architecture = model->architecture;
  s.workspace_hint = fmt::format("every point is outside a leg's reach (L = {:.1f} mm about the slider axes)",
                                 o.model.link_length / kMm);
  if (Status st = validate(o); !st.ok()) return st;
  s.kernel = make_orthoglide_kernel(o);
  return s;
}

// A robot file (docs/robots.md): the box from --box or the file's `workspace:`, the orientation
// task coordinates from --orientation.
StatusOr<MapSetup> robot_setup(const MapArgs& a, Context& ctx) {
  for (const CLI::Option* o : {a.mode_opt, a.assembly_opt, a.region_opt})
    if (Status s = refuse_if_given(o,
                                   "applies to `kinestat map fivebar` only; a robot file takes --box, --step, "
                                   "--orientation, --angles, --angle-step, --position, --method, --load or "
                                   "--wrench");
        !s.ok())
      return s;
  RobotKernelOptions o;
  if (a.method_opt && a.method_opt->count() > 0) {  // a robot file's default is the VJM
    if (a.method != "msa" && a.method != "vjm")
      return Status::Invalid(fmt::format("--method '{}' must be msa or vjm", a.method));
    o.method = a.method == "msa" ? StiffnessMethod::kMsa : StiffnessMethod::kVjm;
  }
  if (Status st = parse_load_options(a.load, a.wrench, o.displacement, o.wrench); !st.ok()) return st;
  auto model = load_robot_model(ctx, "map", a.target, a.out.quiet);
  if (!model.ok()) return model.status();
  auto shared = std::make_shared<const RobotModel>(std::move(*model));
  const RobotDescription& d = shared->description();
  o.model = shared;
  o.task = shared->home_task();
  // Fixed task values: the orientation (deg) and the position (mm) of the coordinates not mapped.
  if (Status st = set_robot_task_values(d, a.orientation, 3, "--orientation", o.task); !st.ok()) return st;
  if (Status st = set_robot_task_values(d, a.position, 0, "--position", o.task); !st.ok()) return st;
  MapSetup s;
  s.angular = !a.angles.empty() || (a.box.empty() && d.workspace && d.workspace_angular);
  if (s.angular && !a.orientation.empty())
    return Status::Invalid("--orientation fixes the angles a map over orientation (--angles) varies; give one");
  if (!s.angular && !a.position.empty())
    return Status::Invalid(
        "--position fixes the position of a map over orientation (--angles); a position map "
        "takes --box");
  if (s.angular ? !a.angle_step : !a.step)
    return Status::Invalid(s.angular ? "--angle-step DEG is required for a map over orientation"
                                     : "--step MM is required with a robot file");
  if (s.angular && a.step) return Status::Invalid("--step (mm) is for position maps; give --angle-step (deg)");
  s.range_option = s.angular ? "--angles" : "--box";
  if (!a.box.empty() && !a.angles.empty()) return Status::Invalid("give --box (a position map) or --angles, not both");
  if (!a.box.empty()) {
    auto r = parse_ranges_mm(a.box, 3, "--box", "x0:x1,y0:y1,z0:z1");
    if (!r.ok()) return r.status();
    s.ranges = {(*r)[0], (*r)[1], (*r)[2]};
  } else if (!a.angles.empty()) {
    // The same lo:hi syntax as --box, in degrees.
    auto r = parse_ranges_mm(a.angles, 3, "--angles", "rx0:rx1,ry0:ry1,rz0:rz1 (deg)");
    if (!r.ok()) return r.status();
    for (int i = 0; i < 3; ++i) s.ranges[i] = {(*r)[i].lo / kMm * kDeg, (*r)[i].hi / kMm * kDeg};
  } else if (d.workspace && d.workspace_angular == s.angular) {
    for (int i = 0; i < 3; ++i) s.ranges[i] = {(*d.workspace)[i].first, (*d.workspace)[i].second};
    s.range_option = fmt::format("{}'s `workspace:`", a.target);
  } else {
    return Status::Invalid(
        fmt::format("{}: no `workspace:` in the file for this map; give {}", a.target,
                    s.angular ? "--angles rx0:rx1,ry0:ry1,rz0:rz1 (deg)" : "--box x0:x1,y0:y1,z0:z1 (mm)"));
  }
  auto axes = robot_grid_axes(d, s.ranges, s.angular, s.range_option);
  if (!axes.ok()) return axes.status();
  o.map_axes = *axes;
  s.with_load = o.displacement || o.wrench;
  s.robot_file = true;
  s.workspace_hint = fmt::format("no posture of {} closes there on the home posture's branch", d.name);
  if (Status st = validate(o); !st.ok()) return st;
  s.kernel = make_robot_kernel(o);
  return s;
}

// "x -100:100 mm, y 0:50 mm, z = 0 mm" (or "rx -10:10 deg, ..." on a grid of angles)
std::string ranges_text(const std::array<MapRange, 3>& ranges, const MapGrid& axes) {
  std::string out;
  for (int i = 0; i < 3; ++i) {
    const MapRange& r = ranges[i];
    const UnitDisplay u = axis_display(axes, i);
    out += r.lo == r.hi
               ? fmt::format("{}{} = {:g} {}", i ? ", " : "", axes.names[i], r.lo * u.scale, u.unit)
               : fmt::format("{}{} {:g}:{:g} {}", i ? ", " : "", axes.names[i], r.lo * u.scale, r.hi * u.scale, u.unit);
  }
  return out;
}

// The axes' kind and names of a setup's grid.
MapGrid grid_axes(bool angular) {
  MapGrid g;
  if (angular) {
    g.angular = {true, true, true};
    g.names = {"rx", "ry", "rz"};
  }
  return g;
}

std::string summary_text(const WorkspaceMap& map, const std::string& step) {
  const MapGrid& g = map.grid;
  std::array<MapRange, 3> extent;
  for (int i = 0; i < 3; ++i) extent[i] = {g.origin(i), g.origin(i) + (g.dimensions[i] - 1) * g.spacing(i)};
  std::string out = fmt::format("{}\n  grid {} x {} x {} = {} points, step {}: {}\n", map.description, g.dimensions[0],
                                g.dimensions[1], g.dimensions[2], g.num_points(), step, ranges_text(extent, g));
  out += "  points:";
  for (int s = 0; s < kNumPostureStatuses; ++s)
    out += fmt::format("{} {} {}", s ? "," : "", map.status_counts[s], to_string(static_cast<PostureStatus>(s)));
  out += fmt::format(" (near-singular: singularity measure < {:g})\n", map.near_singular_threshold);
  const bool volume = g.num_varying_axes() == 3;
  const UnitDisplay m = measure_display(g);
  out += fmt::format("  reachable {} {:.6g} {}", volume ? "volume" : "area", map.reachable_measure * m.scale, m.unit);
  if (map.min_stiffness)
    out += fmt::format("; k_t_min >= {:g} N/mm on {:.6g} {} ({:.1f}% of the reachable)", *map.min_stiffness * kMm,
                       map.stiff_measure * m.scale, m.unit,
                       map.reachable_measure > 0 ? 100.0 * map.stiff_measure / map.reachable_measure : 0.0);
  const UnitDisplay u = axis_display(g, 0);  // the three axes share their kind
  out += fmt::format("\n  {:<20} {:<20} {:>12} {:>12} {:>12}  {}\n", "field", "unit", "min", "max", "mean",
                     fmt::format("min at ({})", u.unit));
  for (const FieldValues& f : map.fields) {
    const io::MapFieldDisplay d = io::map_field_display(f.field);
    const FieldSummary& s = f.summary;
    const Vec3 at = s.argmin * u.scale;
    out += fmt::format("  {:<20} {:<20} {:>12.5g} {:>12.5g} {:>12.5g}  ({:g}, {:g}, {:g})\n", field_info(f.field).name,
                       d.unit, s.min * d.scale, s.max * d.scale, s.mean * d.scale, at.x(), at.y(), at.z());
  }
  return out;
}

int run_map(MapArgs& a, Context& ctx) {
  auto fail = [&](const Status& s) { return report_failure(ctx, kCommand, s); };
  const bool five_bar = a.target == "fivebar";
  if (five_bar && !a.step) a.step = 5.0;
  if (a.step && !(*a.step > 0.0 && std::isfinite(*a.step)))
    return fail(Status::Invalid(fmt::format("--step {:g} mm: the grid step must be positive", *a.step)));
  if (a.angle_step && !(*a.angle_step > 0.0 && std::isfinite(*a.angle_step)))
    return fail(Status::Invalid(fmt::format("--angle-step {:g} deg: the grid step must be positive", *a.angle_step)));
  if (a.min_stiffness && !(*a.min_stiffness >= 0.0 && std::isfinite(*a.min_stiffness)))
    return fail(Status::Invalid(fmt::format("--min-stiffness {:g} N/mm: give a stiffness >= 0", *a.min_stiffness)));
  if (!(a.near_singular >= 0.0 && a.near_singular <= 1.0))
    return fail(Status::Invalid(fmt::format("--near-singular {:g}: the threshold is in [0, 1]", a.near_singular)));
  if (Status st = check_threads_option(a.threads); !st.ok()) return fail(st);
  const std::optional<MapField> field = field_from_name(a.field);
  if (!field)
    return fail(Status::Invalid(fmt::format("--field '{}' is not a map field; use one of {}", a.field, field_names())));

  StatusOr<MapSetup> setup = Status::Ok();
  if (five_bar) {
    setup = five_bar_setup(a);
  } else {
    StatusOr<bool> robot = io::is_robot_file(a.target);
    if (!robot.ok()) return fail(robot.status());
    setup = *robot ? robot_setup(a, ctx) : model_setup(a);
  }
  if (!setup.ok()) return fail(setup.status());
  if ((*field == MapField::kDeflectionTranslation || *field == MapField::kDeflectionRotation) && !setup->with_load)
    return fail(
        Status::Invalid(fmt::format("--field {} needs a load (--load{})", a.field, five_bar ? "" : " or --wrench")));
  // Only the loaded mode of a model iterates; the five-bar's --load is a deflection C w.
  const bool loaded_mode = setup->with_load && !five_bar;
  if (*field == MapField::kNewtonIterations && !loaded_mode)
    return fail(
        Status::Invalid(fmt::format("--field {} needs the loaded mode of a model (--load or --wrench)", a.field)));

  // The grid's step in SI and as the user gave it.
  const double step = setup->angular ? *a.angle_step * kDeg : *a.step * kMm;
  const std::string step_text =
      setup->angular ? fmt::format("{:g} deg", *a.angle_step) : fmt::format("{:g} mm", *a.step);
  const char* step_option = setup->angular ? "--angle-step" : "--step";
  // The point count is estimated before anything is allocated.
  double points = 1.0;
  for (const MapRange& r : setup->ranges) points *= map_axis_points(r, step);
  const std::string region = ranges_text(setup->ranges, grid_axes(setup->angular));
  if (points > static_cast<double>(a.max_points)) {
    // The time it would take, at the sweep kernels' rates per thread (benchmarks/README.md: the
    // built-in ones about 2e5 postures/s unloaded, 1e4 loaded; a robot file's, robot_design_sweep.hpp),
    // so that the limit reads as a cost, not a rule.
    const int threads = a.threads > 0 ? a.threads : available_cpus();
    const double rate = setup->robot_file
                            ? (setup->with_load ? kRobotKernelLoadedPosturesPerSecond : kRobotKernelPosturesPerSecond)
                            : (setup->with_load ? 1e4 : 2e5);
    const double minutes = points / (rate * threads) / 60.0;
    return fail(
        Status::Invalid(fmt::format("{} {} over {} gives {:.3g} points (about {:.2g} min on {} "
                                    "thread{}), more than --max-points {}; use a larger {} or a smaller "
                                    "{}, or raise --max-points",
                                    step_option, step_text, region, points, minutes, threads, threads > 1 ? "s" : "",
                                    a.max_points, step_option, setup->range_option)));
  }
  auto grid = make_map_grid(setup->ranges, step, a.max_points);
  if (!grid.ok())
    return fail(Status::Invalid(
        fmt::format("{} with {} {}: {}", setup->range_option, step_option, step_text, grid.status().message())));
  const MapGrid axes = grid_axes(setup->angular);
  grid->angular = axes.angular;
  grid->names = axes.names;

  MapOptions options;
  options.near_singular_threshold = a.near_singular;
  if (a.min_stiffness) options.min_stiffness = *a.min_stiffness / kMm;
  options.with_deflection = setup->with_load;
  options.with_iterations = loaded_mode;
  options.max_points = a.max_points;
  options.threads = a.threads;
  StatusOr<WorkspaceMap> map = Status::Ok();
  {
    Progress progress(ctx.err, "kinestat map", "points");
    if (!a.out.quiet) options.progress = [&progress](std::size_t done, std::size_t total) { progress(done, total); };
    map = compute_workspace_map(*setup->kernel, *grid, options);
  }
  if (!map.ok()) return fail(map.status());
  if (map->status_counts[static_cast<int>(PostureStatus::kUnreachable)] == grid->num_points())
    return fail(Status::Invalid(fmt::format("no reachable point in {} ({}) for {}: {}; nothing written",
                                            setup->range_option, region, map->description, setup->workspace_hint)));
  // Reachable points, none with a stiffness (a load past buckling everywhere, a region on a
  // singular locus): a summary of NaN would look like a result.
  const auto count = [&map](PostureStatus s) { return map->status_counts[static_cast<int>(s)]; };
  if (count(PostureStatus::kOk) + count(PostureStatus::kNearSingular) == 0) {
    const std::size_t failed = count(PostureStatus::kFailed), singular = count(PostureStatus::kSingular);
    const std::string what = fmt::format(
        "no point of {} ({}) has a stiffness: {} failed, {} singular, {} unreachable; "
        "nothing written",
        setup->range_option, region, failed, singular, count(PostureStatus::kUnreachable));
    if (failed > 0 && (!a.load.empty() || !a.wrench.empty()))
      return fail(Status::NotConverged(what + ". The loaded equilibrium was not found at any posture: the load may "
                                              "exceed the buckling load; give a smaller --load or --wrench"));
    if (failed > 0) return fail(Status::NotConverged(what + ". `kinestat vjm` at one of these points says why"));
    return fail(Status::Singular(what + "; choose a region away from the singular loci"));
  }
  map->curves = std::move(setup->curves);

  std::vector<std::string> written;
  if (!a.vti.empty()) {
    if (Status s = io::write_map_vti(a.vti, *map); !s.ok()) return fail(s);
    written.push_back(a.vti);
  }
  if (!a.png.empty()) {
    if (Status s = io::write_workspace_map_png(a.png, *map, *field); !s.ok()) return fail(s);
    written.push_back(a.png);
  }
  Output output(ctx, a.out);
  if (output.json_wanted()) {
    // Compact: a map holds ~15 numbers per point.
    if (Status s = output.write_json(io::workspace_map_to_json(*map), -1); !s.ok()) return fail(s);
    if (a.out.json != "-") written.push_back(a.out.json);
  }
  std::ostream& out = output.report();
  out << summary_text(*map, step_text);
  for (const std::string& w : written) out << "  wrote " << w << "\n";
  return kExitOk;
}

}  // namespace

void register_map_command(CLI::App& app, Context& ctx) {
  auto a = std::make_shared<MapArgs>();
  CLI::App* cmd = app.add_subcommand(
      "map",
      "workspace stiffness map (docs/maps.md): the tool-point stiffness at every point of a grid, as VTI "
      "(ParaView), JSON and PNG. Targets: `fivebar` (the 5R five-bar of Goncalves et al. 2010, the plane "
      "of P), a VJM model file with `mechanism: orthoglide` (a 3D box or a slice) or a robot file (`robot:`, "
      "docs/robots.md; models/robots/)");
  cmd->add_option("target", a->target,
                  "`fivebar`, a VJM model file (YAML, mechanism: orthoglide) or a robot file (YAML, robot:)")
      ->required();
  a->mode_opt = cmd->add_option("--mode", a->mode, "fivebar: working mode ++ (default), +-, -+ or --");
  a->assembly_opt = cmd->add_option("--assembly", a->assembly, "fivebar: assembly mode up (default) or down");
  a->method_opt = cmd->add_option("--method", a->method,
                                  "stiffness by msa or vjm (fivebar: msa by default; a robot file: vjm by default, msa "
                                  "unloaded only)");
  a->region_opt = cmd->add_option("--region", a->region,
                                  "fivebar: x0:x1,y0:y1 in mm (default: the bounding box of the mode's workspace)")
                      ->delimiter(',');
  a->box_opt =
      cmd->add_option("--box", a->box, "model: x0:x1,y0:y1,z0:z1 in mm (a single value for one axis: a 2D slice)")
          ->delimiter(',');
  cmd->add_option("--step", a->step, "grid step in mm (fivebar default 5)");
  a->angles_opt = cmd->add_option("--angles", a->angles,
                                  "robot file: a map over the orientation rx0:rx1,ry0:ry1,rz0:rz1 in deg (a single "
                                  "value: fixed), at --position")
                      ->delimiter(',');
  a->angle_step_opt = cmd->add_option("--angle-step", a->angle_step, "robot file: the --angles grid step in deg");
  a->position_opt = cmd->add_option("--position", a->position,
                                    "robot file: the tool position x,y,z in mm of a map over orientation (default: "
                                    "home's)")
                        ->delimiter(',');
  a->orientation_opt = cmd->add_option("--orientation", a->orientation,
                                       "robot file: the tool's orientation rx,ry,rz in deg (Rz Ry Rx, base axes) for "
                                       "the task's angles at every point (default: home's, 0)")
                           ->delimiter(',');
  CLI::Option* load = cmd->add_option("--load", a->load,
                                      "fivebar: wrench at P Fx,Fy,Fz (N), Mx,My,Mz (N mm) for the deflection fields; "
                                      "model: prescribed tool displacement dx,dy,dz (mm), rx,ry,rz (deg), loaded mode")
                          ->delimiter(',');
  a->wrench_opt = cmd->add_option("--wrench", a->wrench,
                                  "model: external wrench Fx,Fy,Fz (N), Mx,My,Mz (N mm) at the tool point, loaded mode")
                      ->delimiter(',')
                      ->excludes(load);
  cmd->add_option("--min-stiffness", a->min_stiffness,
                  "stiffness threshold K in N/mm: the summary gives the area/volume where k_t_min >= K");
  cmd->add_option("--near-singular", a->near_singular,
                  "points whose singularity measure (0..1) is below this are near-singular (default 0.01)");
  cmd->add_option("--max-points", a->max_points, "refuse grids with more points than this (default 2000000)")
      ->check(positive_number());  // a size_t would take -1 as 2^64 - 1
  cmd->add_option("--threads", a->threads, "threads (default 0: all cores)");
  cmd->add_option("--vti", a->vti, "write the map as VTK ImageData (.vti) for ParaView");
  cmd->add_option("--png", a->png, "write a PNG of --field (a box: a sheet of z slices)");
  cmd->add_option("--field", a->field, "field of the PNG (default k_t_min; docs/maps.md lists them)");
  add_output_options(*cmd, a->out, "kinestat-workspace-map", "docs/maps.md");
  cmd->callback([a, &ctx] { ctx.exit_code = run_map(*a, ctx); });
}

}  // namespace kinestat::cli
