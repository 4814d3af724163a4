#include "kinestat/cli/app.hpp"

#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "kinestat/core/types.hpp"
#include "kinestat/core/version.hpp"
#include "kinestat/solver/library_versions.hpp"
#include "kinestat/solver/parallel.hpp"

namespace kinestat::cli {
namespace {

// `kinestat --version`: ours, then the libraries the numbers depend on. CHOLMOD, the BLAS and PETSc's
// module as loaded at run time (the BLAS is a Debian alternative, chosen at run time); the header-only and
// the VTK libraries as built against (KINESTAT_*_VERSION from src/cli/CMakeLists.txt).
std::string version_text() {
  const solver::LibraryVersions v = solver::library_versions();
  return fmt::format(
      "kinestat {}\n  sparse Cholesky: {}\n  BLAS: {}\n  distributed backends: {}\n  built with Eigen {}.{}.{}, VTK "
      "{}, CGAL {}",
      kVersion, v.cholmod, v.blas, solver::petsc_versions(), EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
      EIGEN_MINOR_VERSION, KINESTAT_VTK_VERSION, KINESTAT_CGAL_VERSION);
}

// "solve", "design orthoglide", ...: the subcommands selected so far, for messages.
std::string selected_command(const CLI::App& app) {
  std::string name;
  for (const CLI::App* a = &app; !a->get_subcommands().empty();) {
    a = a->get_subcommands().front();
    name += (name.empty() ? "" : " ") + a->get_name();
  }
  return name;
}

}  // namespace

int exit_code_for(const Status& status) {
  switch (status.code()) {
    case StatusCode::kOk:
      return kExitOk;
    case StatusCode::kInvalidInput:
      return kExitBadInput;
    // An iterative method that does not converge on the user's input (a load beyond the buckling load,
    // targets no model meets): a property of the input, reported with its reason.
    case StatusCode::kNotConverged:
      return kExitBadInput;
    case StatusCode::kSingular:
      return kExitSingular;
    default:
      return kExitInternal;
  }
}

int report_failure(Context& ctx, const std::string& command, const Status& status) {
  ctx.failure = "kinestat" + (command.empty() ? "" : " " + command) + ": " + status.message();
  ctx.err << ctx.failure << "\n";
  return exit_code_for(status);
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{
      "kinestat: stiffness of robots and frames (MSA, VJM, FEA). Options are in mm, deg, N, N mm, MPa "
      "(each option says its unit); files declare their own units; JSON and VTK are SI.",
      "kinestat"};
  app.require_subcommand(1);
  app.set_version_flag("--version", version_text, "print the version of kinestat and of the libraries it uses");
  Context ctx{out, err};
  for (const std::string& a : args) ctx.command_line += (ctx.command_line.empty() ? "" : " ") + a;
  // Every subcommand is listed here once.
  for (const CommandRegistrar& r : std::initializer_list<CommandRegistrar>{
           register_solve_command,
           register_buckling_command,
           register_modes_command,
           register_fivebar_command,
           register_design_command,
           register_vjm_command,
           register_link_stiffness_command,
           register_identify_command,
           register_map_command,
       })
    r(app, ctx);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e, out, err), kExitOk;  // --help, --version
    const std::string command = selected_command(app);
    return report_failure(
        ctx, command,
        Status::Invalid(fmt::format("{}; see kinestat {}--help", e.what(), command.empty() ? "" : command + " ")));
  }
  // A report or JSON lost on stdout (a full disk, a closed pipe) is a failed run, not a success. (A
  // run that failed already has said so; its report is not worth a second message.)
  if (!out.flush() && (ctx.exit_code == kExitOk || ctx.exit_code == kExitSingular))
    return report_failure(ctx, selected_command(app),
                          Status::Invalid("stdout: writing the output failed (a full disk or a closed pipe?); "
                                          "write it to a file with room"));
  return solver::finish_job(ctx.exit_code, ctx.failure);
}

}  // namespace kinestat::cli
