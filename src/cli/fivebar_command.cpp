// kinestat fivebar --theta1 DEG --theta2 DEG [--assembly up|down] | --point X,Y [--mode ++]
// The 5R five-bar of Gonçalves et al. 2010 (section 5) built and solved at one posture.
#include <optional>
#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/msa_output.hpp"
#include "kinestat/core/units.hpp"
#include "kinestat/mechanisms/five_bar.hpp"

namespace kinestat::cli {
namespace {

using units::kDeg;
using units::kMm;

struct FiveBarArgs {
  std::optional<double> theta1, theta2;  // deg
  std::string assembly = "up";
  std::vector<double> point;  // x, y in mm
  std::string mode = "++";
  bool regularize = false;
  MsaOutputOptions out;
};

StatusOr<mechanisms::FiveBarPosture> posture_from(const FiveBarArgs& a, const mechanisms::FiveBarParams& p) {
  if (!a.point.empty()) {
    if (a.point.size() != 2) return Status::Invalid("--point takes two numbers: x,y in mm");
    const auto mode = mechanisms::working_mode_from_name(a.mode);
    if (!mode) return Status::Invalid(fmt::format("--mode '{}' is not a working mode; use ++, +-, -+ or --", a.mode));
    auto q = mechanisms::inverse_kinematics(p, mechanisms::Vec2(a.point[0], a.point[1]) * kMm, *mode);
    if (!q.ok())  // the library speaks SI: say which option, in its unit, it is about
      return Status(q.status().code(),
                    fmt::format("--point {},{} mm: {}", a.point[0], a.point[1], q.status().message()));
    return q;
  }
  if (!a.theta1 || !a.theta2)
    return Status::Invalid("give the posture as --theta1 DEG --theta2 DEG, or --point X,Y (mm)");
  const auto assembly = mechanisms::assembly_from_name(a.assembly);
  if (!assembly) return Status::Invalid(fmt::format("--assembly '{}' must be up or down", a.assembly));
  return mechanisms::direct_kinematics(p, *a.theta1 * kDeg, *a.theta2 * kDeg, *assembly);
}

}  // namespace

void register_fivebar_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<FiveBarArgs>();
  CLI::App* cmd =
      app.add_subcommand("fivebar",
                         "the 5R five-bar of Gonçalves et al. 2010 (r1 = r2 = r3 = 100 mm): kinematics, MSA stiffness, "
                         "singularity diagnosis at one posture; the MSA report, JSON and VTK are in SI units");
  CLI::Option* theta1 = cmd->add_option("--theta1", args->theta1, "input angle of the left actuator (deg)");
  CLI::Option* theta2 = cmd->add_option("--theta2", args->theta2, "input angle of the right actuator (deg)");
  cmd->add_option("--assembly", args->assembly, "assembly mode with the angles: up (default) or down")
      ->needs(theta1)
      ->needs(theta2);
  CLI::Option* point =
      cmd->add_option("--point", args->point, "platform point x,y (mm) instead of the angles")->delimiter(',');
  point->excludes(theta1)->excludes(theta2);
  cmd->add_option("--mode", args->mode, "working mode with --point: ++ (default), +-, -+, --")->needs(point);
  cmd->add_flag("--regularize", args->regularize, "at a singular posture, also print a marked, regularized answer");
  add_msa_output_options(*cmd, args->out);
  cmd->callback([args, &ctx] {
    const mechanisms::FiveBarParams params;
    auto q = posture_from(*args, params);
    if (!q.ok()) {
      ctx.exit_code = report_failure(ctx, "fivebar", q.status());
      return;
    }
    const auto jac = mechanisms::five_bar_jacobians(*q);
    Output out(ctx, args->out.out);
    out.report() << fmt::format(
        "five-bar posture: theta1 = {:.4f} deg, theta2 = {:.4f} deg, P = ({:.4f}, {:.4f}) mm, "
        "working mode {}, assembly {}\n",
        q->theta1 / kDeg, q->theta2 / kDeg, q->P.x() / kMm, q->P.y() / kMm, to_string(q->working_mode),
        to_string(q->assembly));
    out.report() << fmt::format(
        "kinematic singularity measures (0 = singular): parallel {:.3e}{}, serial {:.3e}{}\n\n", jac.parallel_measure,
        jac.parallel_singular() ? " (PARALLEL SINGULAR: B1P, PB2 aligned)" : "", jac.serial_measure,
        jac.serial_singular() ? " (SERIAL SINGULAR: a leg stretched/folded)" : "");
    const msa::Structure s = mechanisms::make_five_bar_structure(params, *q);
    msa::SolveOptions opt;
    opt.regularize = args->regularize;
    args->out.basename = "five_bar";
    const nlohmann::json posture = {{"five_bar",
                                     {{"theta1", q->theta1},
                                      {"theta2", q->theta2},
                                      {"point", {q->P.x(), q->P.y()}},
                                      {"working_mode", to_string(q->working_mode)},
                                      {"assembly", to_string(q->assembly)},
                                      {"parallel_singularity_measure", jac.parallel_measure},
                                      {"serial_singularity_measure", jac.serial_measure},
                                      {"parallel_singular", jac.parallel_singular()},
                                      {"serial_singular", jac.serial_singular()}}}};
    ctx.exit_code = finish_msa_run("fivebar", s, msa::solve(s, opt), args->out, ctx, posture);
  });
}

}  // namespace kinestat::cli
