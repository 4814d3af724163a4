#include "kinestat/cli/app.hpp"

#include <ostream>

#include <CLI/CLI.hpp>

namespace kinestat::cli {

int exit_code_for(const Status& status) {
  switch (status.code()) {
    case StatusCode::kOk: return kExitOk;
    case StatusCode::kInvalidInput: return kExitBadInput;
    case StatusCode::kSingular: return kExitSingular;
    default: return kExitInternal;
  }
}

int report_failure(Context& ctx, const std::string& command, const Status& status) {
  ctx.err << "kinestat " << command << ": " << status.message() << "\n";
  return exit_code_for(status);
}

int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"kinestat: stiffness of robots and frames (MSA, VJM, FEA). SI units unless a file says otherwise.",
               "kinestat"};
  app.require_subcommand(1);
  Context ctx{out, err};
  // Every subcommand is listed here once.
  for (const CommandRegistrar& r : std::initializer_list<CommandRegistrar>{
           register_solve_command,
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
    // --help prints and returns 0; a bad option prints CLI11's message and is bad input.
    return app.exit(e, out, err) == 0 ? kExitOk : kExitBadInput;
  }
  return ctx.exit_code;
}

}  // namespace kinestat::cli
