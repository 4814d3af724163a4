// The kinestat command line, as a library: tests call run() with argument vectors and streams.
// Exit status: 0 success, 2 bad input (model, mesh, option, impossible posture),
// 3 the structure is singular at this posture (the diagnosis is printed), 1 internal failure.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"

namespace CLI {
class App;
}

namespace kinestat::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitSingular = 3;

// The exit status for a library status: kOk 0, kInvalidInput and kNotConverged 2, kSingular 3, anything
// else 1.
int exit_code_for(const Status& status);

// What a subcommand writes to and returns through.
struct Context {
  std::ostream& out;
  std::ostream& err;
  int exit_code = kExitOk;
  std::string command_line{};  // the arguments joined by spaces (compared across MPI ranks)
  std::string failure{};       // the message of a failed command, for solver::finish_job under MPI
};

// Prints "kinestat COMMAND: message" to ctx.err and keeps it in ctx.failure; returns the exit status
// for `status`.
int report_failure(Context& ctx, const std::string& command, const Status& status);

// A subcommand adds itself to the app; its callback runs when it is selected and sets ctx.exit_code.
using CommandRegistrar = std::function<void(CLI::App& app, Context& ctx)>;

// The subcommands (one file each: solve_command.cpp, fivebar_command.cpp, ...).
void register_solve_command(CLI::App& app, Context& ctx);
void register_buckling_command(CLI::App& app, Context& ctx);
void register_modes_command(CLI::App& app, Context& ctx);
void register_fivebar_command(CLI::App& app, Context& ctx);
void register_design_command(CLI::App& app, Context& ctx);
void register_vjm_command(CLI::App& app, Context& ctx);
void register_link_stiffness_command(CLI::App& app, Context& ctx);
void register_identify_command(CLI::App& app, Context& ctx);
void register_map_command(CLI::App& app, Context& ctx);

// Runs `kinestat ARGS...` (args excludes the program name). Under mpirun it ends with
// solver::finish_job, so that a rank that failed alone ends the job instead of leaving it hanging.
int run(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace kinestat::cli
