// What every MSA-based command does after solving: print the report, write JSON and VTK, and
// turn the solution's status into the exit code. Shared by `solve` and `fivebar`.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "cli/command_output.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::cli {

struct MsaOutputOptions {
  OutputOptions out;      // --json, --quiet
  std::string vtk_dir;    // empty: no VTK
  std::string basename;   // of the .vtu/.pvd files
  int stations = 0;       // --stations: along-member results per beam in the JSON (0: none)
};

// Adds --vtk, --json and --quiet to a command.
void add_msa_output_options(CLI::App& cmd, MsaOutputOptions& o);

// Returns the exit status: 0 solved, 3 singular (diagnosis printed; files still written so the free
// motions can be seen in ParaView), 2 invalid model or unwritable output, 1 internal failure.
// `extra` holds fields added to the JSON document (the five-bar's posture).
int finish_msa_run(const std::string& command, const msa::Structure& s, const msa::Solution& sol,
                   const MsaOutputOptions& o, Context& ctx, const nlohmann::json& extra = nlohmann::json::object());

}  // namespace kinestat::cli
