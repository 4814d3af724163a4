// kinestat fivebar --theta1 DEG --theta2 DEG [--assembly up|down] | --point X,Y [--mode ++]
// The 5R five-bar of Gonçalves et al. 2010 (section 5) built and solved at one posture.
#include <numbers>
#include <ostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "cli/msa_output.hpp"
#include "kinestat/mechanisms/five_bar.hpp"

namespace kinestat::cli {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct FiveBarArgs {
  std::optional<double> theta1, theta2;  // deg
  std::string assembly = "up";
  std::vector<double> point;             // x, y in m
  std::string mode = "++";
  bool regularize = false;
  MsaOutputOptions out;
};

StatusOr<mechanisms::FiveBarPosture> posture_from(const FiveBarArgs& a, const mechanisms::FiveBarParams& p) {
  if (!a.point.empty()) {
    if (a.point.size() != 2) return Status::Invalid("--point takes two numbers: x,y in m");
    const auto mode = mechanisms::working_mode_from_name(a.mode);
    if (!mode) return Status::Invalid(fmt::format("--mode '{}' is not a working mode; use ++, +-, -+ or --", a.mode));
    return mechanisms::inverse_kinematics(p, mechanisms::Vec2(a.point[0], a.point[1]), *mode);
  }
  if (!a.theta1 || !a.theta2) return Status::Invalid("give the posture as --theta1 DEG --theta2 DEG, or --point X,Y");
  const auto assembly = mechanisms::assembly_from_name(a.assembly);
  if (!assembly) return Status::Invalid(fmt::format("--assembly '{}' must be up or down", a.assembly));
  return mechanisms::direct_kinematics(p, *a.theta1 * kDeg, *a.theta2 * kDeg, *assembly);
}

}  // namespace

void register_fivebar_command(CLI::App& app, Context& ctx) {
  auto args = std::make_shared<FiveBarArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fivebar", "the 5R five-bar of Gonçalves et al. 2010 (r1 = r2 = r3 = 0.1 m): kinematics, MSA stiffness, "
                 "singularity diagnosis at one posture");
  cmd->add_option("--theta1", args->theta1, "input angle of the left actuator (deg)");
  cmd->add_option("--theta2", args->theta2, "input angle of the right actuator (deg)");
  cmd->add_option("--assembly", args->assembly, "assembly mode: up (default) or down");
  cmd->add_option("--point", args->point, "platform point x,y (m) instead of the angles")->delimiter(',');
  cmd->add_option("--mode", args->mode, "working mode with --point: ++ (default), +-, -+, --");
  cmd->add_flag("--regularize", args->regularize, "at a singular posture, also print a marked, regularized answer");
  add_msa_output_options(*cmd, args->out);
  cmd->callback([args, &ctx] {
    const mechanisms::FiveBarParams params;
    auto q = posture_from(*args, params);
    if (!q.ok()) {
      ctx.err << "kinestat fivebar: " << q.status().message() << "\n";
      ctx.exit_code = kExitBadInput;
      return;
    }
    const auto jac = mechanisms::five_bar_jacobians(*q);
    if (!args->out.quiet) {
      ctx.out << fmt::format("five-bar posture: theta1 = {:.4f} deg, theta2 = {:.4f} deg, P = ({:.6f}, {:.6f}) m, "
                             "working mode {}, assembly {}\n",
                             q->theta1 / kDeg, q->theta2 / kDeg, q->P.x(), q->P.y(), to_string(q->working_mode),
                             to_string(q->assembly));
      ctx.out << fmt::format("kinematic singularity measures (0 = singular): parallel {:.3e}{}, serial {:.3e}{}\n\n",
                             jac.parallel_measure, jac.parallel_singular() ? " (PARALLEL SINGULAR: B1P, PB2 aligned)" : "",
                             jac.serial_measure, jac.serial_singular() ? " (SERIAL SINGULAR: a leg stretched/folded)" : "");
    }
    const msa::Structure s = mechanisms::make_five_bar_structure(params, *q);
    msa::SolveOptions opt;
    opt.regularize = args->regularize;
    args->out.basename = "five_bar";
    ctx.exit_code = finish_msa_run(s, msa::solve(s, opt), args->out, ctx);
  });
}

}  // namespace kinestat::cli
