// What every MSA-based command does after solving: print the report, write JSON and VTK, and
// turn the solution's status into the exit code. Shared by `solve` and `fivebar`.
#pragma once

#include <string>

#include "kinestat/cli/app.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::cli {

struct MsaOutputOptions {
  std::string vtk_dir;    // empty: no VTK
  std::string json_path;  // empty: no JSON
  std::string basename;   // of the .vtu/.pvd files
  bool quiet = false;     // no report on stdout (files and errors only)
};

// Returns the exit status: 0 solved, 3 singular (diagnosis printed; files still written so the free
// motions can be seen in ParaView), 2 invalid model, 1 internal failure.
int finish_msa_run(const msa::Structure& s, const msa::Solution& sol, const MsaOutputOptions& o, Context& ctx);

// Adds --vtk, --json and --quiet to a command.
void add_msa_output_options(CLI::App& cmd, MsaOutputOptions& o);

}  // namespace kinestat::cli
