// kinestat vjm MODEL|ROBOT [--point x,y,z] [--orientation rx,ry,rz] [--load dx,dy,dz,rx,ry,rz | --wrench
// Fx,Fy,Fz,Mx,My,Mz] [--json FILE|-] Virtual joint method stiffness (Pashkevich et al. 2009) of a platform read from a
// VJM model file (docs/vjm.md): unloaded (eq. 9-10) and, with a load, loaded (eq. 11-21).
#include <sstream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/command_output.hpp"
#include "cli/grid_options.hpp"
#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/io/vjm_results_json.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/mechanisms/robot_model.hpp"
#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::cli {
namespace {

using units::kDeg;
using units::kMm;
using units::kNMm;

struct VjmArgs {
  std::string model;
  std::vector<double> point;        // mm
  std::vector<double> orientation;  // deg (robot files)
  std::vector<double> load;         // mm, deg
  std::vector<double> wrench;       // N, N mm
  int max_coordinates = vjm::kDefaultMaxChainCoordinates;
  OutputOptions out;
};

// A robot file's chains at the posture of --point (mm) and --orientation (deg): the task's
// coordinates taken from them (home's where not given), the closed-loop kinematics solved from home
// (docs/robots.md), and the joint values in words for the report.
struct ModelChains {
  std::vector<vjm::Chain> chains;
  std::string title, posture;
};

StatusOr<ModelChains> robot_chains(const VjmArgs& a, Context& ctx) {
  auto model = load_robot_model(ctx, "vjm", a.model, a.out.quiet);
  if (!model.ok()) return model.status();
  const mechanisms::RobotDescription& d = model->description();
  VecX task = model->home_task();
  if (Status st = set_robot_task_values(d, a.point, 0, "--point", task); !st.ok()) return st;
  if (Status st = set_robot_task_values(d, a.orientation, 3, "--orientation", task); !st.ok()) return st;
  mechanisms::RobotData data = mechanisms::make_robot_data(*model);
  mechanisms::RobotPosture posture = model->home();
  const mechanisms::KinematicsResult k = mechanisms::solve_posture(*model, task, posture, data);
  if (k.status == mechanisms::KinematicsStatus::kSingular)
    return Status::Singular(fmt::format("{}: the posture is singular: {}", a.model, k.message));
  if (k.status != mechanisms::KinematicsStatus::kOk)
    return Status::Invalid(
        fmt::format("{}: the task values are not reached from home ({}): {}; choose a point "
                    "inside the workspace",
                    a.model, to_string(k.status), k.message));
  ModelChains out;
  out.title = d.name;
  out.posture = fmt::format("  posture solved from home in {} Newton steps; singularity measure {:.4g}\n", k.iterations,
                            k.singularity_measure);
  for (int i = 0; i < model->num_coordinates(); ++i) {
    const mechanisms::RobotModel::Coordinate& c = model->coordinates()[i];
    const mechanisms::RobotJoint& j = model->joint(c);
    const bool length = mechanisms::coordinate_is_length(j.type, c.index);
    out.posture += fmt::format("    {:<60} {:>12.6f} {}{}\n", model->coordinate_name(i),
                               length ? posture.q(i) / kMm : posture.q(i) / kDeg, length ? "mm" : "deg",
                               model->actuated(c) ? "  (actuated)" : "");
  }
  out.chains = mechanisms::robot_vjm_chains(*model, posture);
  return out;
}

// The stiffness, compliance, indices and lost directions of one VJM result.
std::string stiffness_report(const CartesianStiffness& K, const std::string& what) {
  return cartesian_stiffness_report(K, "Cartesian stiffness (" + what + ")");
}

int run_vjm(const VjmArgs& a, Context& ctx) {
  auto bad = [&](const Status& s) { return report_failure(ctx, "vjm", s); };
  // The options first, in SI: a bad one is reported before any result.
  std::optional<Vec3> point;
  if (!a.point.empty()) {
    StatusOr<Vec3> p = parse_point_option(a.point, "--point");
    if (!p.ok()) return bad(p.status());
    point = *p;
  }
  std::optional<Vec6> displacement, wrench;
  if (!a.load.empty()) {
    StatusOr<Vec6> d = parse_displacement_option(a.load, "--load");
    if (!d.ok()) return bad(d.status());
    displacement = *d;
  }
  if (!a.wrench.empty()) {
    StatusOr<Vec6> w = parse_wrench_option(a.wrench, "--wrench");
    if (!w.ok()) return bad(w.status());
    wrench = *w;
  }
  StatusOr<bool> robot = io::is_robot_file(a.model);
  if (!robot.ok()) return bad(robot.status());
  if (!*robot && !a.orientation.empty())
    return bad(Status::Invalid("--orientation applies to robot files (docs/robots.md)"));
  StatusOr<ModelChains> model = Status::Ok();
  if (*robot) {
    model = robot_chains(a, ctx);
  } else {
    StatusOr<io::VjmModel> vjm_model = io::read_vjm_model_yaml(a.model);
    if (!vjm_model.ok()) return bad(vjm_model.status());
    // The model's `fea:` link springs: meshing and FEA (or their cache), with progress on stderr.
    auto progress = [&ctx, &a](const std::string& stage) {
      if (!a.out.quiet) ctx.err << "vjm: " << stage << " ...\n";
    };
    // Warnings even with --quiet: a cache entry was damaged and its result recomputed.
    auto warning = [&ctx](const std::string& w) { ctx.err << "vjm: warning: " << w << "\n"; };
    if (Status s = io::resolve_fea_springs(*vjm_model, progress, warning); !s.ok()) return bad(s);
    StatusOr<std::vector<vjm::Chain>> c = io::vjm_model_chains(*vjm_model, point);
    // A point out of reach is the option's: named as fivebar's --point is.
    if (!c.ok() && point && c.status().message().find("out of reach") != std::string::npos)
      return bad(Status(c.status().code(), fmt::format("--point {:g},{:g},{:g} mm: {}", a.point[0], a.point[1],
                                                       a.point[2], c.status().message())));
    if (!c.ok()) return bad(c.status());
    model = ModelChains{std::move(*c), vjm_model->title, ""};
  }
  if (!model.ok()) return bad(model.status());
  const std::vector<vjm::Chain>* chains = &model->chains;
  vjm::StiffnessOptions stiffness_options;
  stiffness_options.max_chain_coordinates = a.max_coordinates;
  vjm::EquilibriumOptions equilibrium_options;
  equilibrium_options.max_chain_coordinates = a.max_coordinates;
  StatusOr<CartesianStiffness> K0 = vjm::platform_unloaded_stiffness(*chains, stiffness_options);
  if (!K0.ok()) return bad(K0.status());

  io::VjmResults results;
  results.model_file = a.model;
  results.title = model->title;
  results.num_chains = static_cast<int>(chains->size());
  results.tool_point = chains->front().nominal_pose().translation();
  results.unloaded = *K0;
  Output out(ctx, a.out);
  out.report() << fmt::format("kinestat VJM report{}\n", model->title.empty() ? "" : ": " + model->title);
  const Vec3 tool = results.tool_point / kMm;
  out.report() << fmt::format("  {} chains; tool point ({:.4f}, {:.4f}, {:.4f}) mm\n", chains->size(), tool.x(),
                              tool.y(), tool.z())
               << model->posture << "\n"
               << stiffness_report(*K0, "unloaded, eq. 10");
  Status result = K0->status;

  if (displacement || wrench) {
    StatusOr<vjm::PlatformState> state =
        displacement ? vjm::platform_equilibrium(*chains, *displacement, equilibrium_options)
                     : vjm::platform_equilibrium_under_wrench(*chains, *wrench, equilibrium_options);
    // A load whose equilibrium is not found: how much of it is, so that the fix has a number.
    if (!state.ok() && state.status().code() == StatusCode::kNotConverged) {
      const vjm::LoadShare share = vjm::load_share_reached(*chains, displacement ? &*displacement : nullptr,
                                                           wrench ? &*wrench : nullptr, equilibrium_options);
      const char* option = displacement ? "--load" : "--wrench";
      const char* units = displacement ? "mm and deg" : "N and N mm";
      return bad(Status::NotConverged(
          share.found > 0.0
              ? fmt::format("{}. The equilibrium is found under {:.1f} % of this load and not under {:.1f} %: give a "
                            "smaller {} (at most {:.3g} times this one), or check its units ({})",
                            state.status().message(), 100 * share.found, 100 * share.failed, option, share.found, units)
              : fmt::format("{}. It is not found under {:.1f} % of this load either: check the direction and the "
                            "units ({}) of {}",
                            state.status().message(), 100 * share.failed, units, option)));
    }
    if (!state.ok()) return bad(state.status());
    const Vec6& t = state->displacement;
    const Vec6& F = state->wrench;
    out.report() << fmt::format("\nloaded equilibrium: {}\n", state->report.summary())
                 << fmt::format("  displacement ({:.6e}, {:.6e}, {:.6e}) mm, rotation ({:.6e}, {:.6e}, {:.6e}) deg\n",
                                t(0) / kMm, t(1) / kMm, t(2) / kMm, t(3) / kDeg, t(4) / kDeg, t(5) / kDeg)
                 << fmt::format("  wrench F = ({:.6e}, {:.6e}, {:.6e}) N, M = ({:.6e}, {:.6e}, {:.6e}) N mm\n", F(0),
                                F(1), F(2), F(3) / kNMm, F(4) / kNMm, F(5) / kNMm);
    results.state = *state;
    StatusOr<CartesianStiffness> KF = vjm::platform_loaded_stiffness(*chains, *state, stiffness_options);
    if (!KF.ok()) return bad(KF.status());
    results.loaded = *KF;
    out.report() << stiffness_report(*KF, "loaded, eq. 21");
    if (result.ok()) result = KF->status;
  }
  if (Status s = out.write_json(io::vjm_results_to_json(results)); !s.ok()) return bad(s);
  return out.finish("vjm", result);
}

}  // namespace

void register_vjm_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<VjmArgs>();
  CLI::App* cmd = app.add_subcommand(
      "vjm",
      "virtual joint method stiffness of a VJM model file (docs/vjm.md) or a robot file (docs/robots.md) "
      "at one posture (their numbers are in the file's 'units:'): unloaded, and loaded under --load or "
      "--wrench; stiffness printed in SI units");
  cmd->add_option("model", args->model, "VJM model file or robot file (YAML)")->required();
  cmd->add_option("--point", args->point,
                  "tool point x,y,z in mm (Orthoglide models, default Q0 = 0,0,0; robot files, default home)")
      ->delimiter(',');
  cmd->add_option("--orientation", args->orientation,
                  "robot files: the tool's orientation rx,ry,rz in deg for the task's angles (default home's, 0)")
      ->delimiter(',');
  CLI::Option* load =
      cmd->add_option("--load", args->load, "prescribed tool displacement dx,dy,dz (mm), rx,ry,rz (deg): loaded mode")
          ->delimiter(',');
  cmd->add_option("--wrench", args->wrench,
                  "external wrench Fx,Fy,Fz (N), Mx,My,Mz (N mm) about the tool point: loaded mode")
      ->delimiter(',')
      ->excludes(load);
  cmd->add_option("--max-coordinates", args->max_coordinates,
                  "refuse a chain with more coordinates (passive and virtual) than this: its dense matrices grow "
                  "as the square")
      ->capture_default_str()
      ->check(positive_number());
  add_output_options(*cmd, args->out, "kinestat-vjm-results");
  cmd->callback([args, &ctx] { ctx.exit_code = run_vjm(*args, ctx); });
}

}  // namespace kinestat::cli
