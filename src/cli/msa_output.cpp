#include "cli/msa_output.hpp"

#include <filesystem>
#include <ostream>

#include <CLI/CLI.hpp>

#include "kinestat/io/results_json.hpp"
#include "kinestat/io/vtk_output.hpp"

namespace kinestat::cli {

void add_msa_output_options(CLI::App& cmd, MsaOutputOptions& o) {
  cmd.add_option("--vtk", o.vtk_dir, "write ParaView files (.vtu per load case + .pvd) into this folder");
  cmd.add_option("--json", o.json_path, "write the results as JSON (schema: docs/results-json.md)");
  cmd.add_flag("--quiet", o.quiet, "print no report (errors still go to stderr)");
}

int finish_msa_run(const msa::Structure& s, const msa::Solution& sol, const MsaOutputOptions& o, Context& ctx) {
  const StatusCode code = sol.status.code();
  if (code == StatusCode::kInvalidInput || code == StatusCode::kInternal) {
    ctx.err << "kinestat: " << sol.status.message() << "\n";
    return exit_code_for(sol.status);
  }
  if (!o.quiet) ctx.out << msa::full_report(s, sol);
  if (!o.json_path.empty()) {
    std::error_code ec;  // the folder may not exist yet; write_json reports what still fails
    if (const auto parent = std::filesystem::path(o.json_path).parent_path(); !parent.empty())
      std::filesystem::create_directories(parent, ec);
    if (Status st = io::write_json(o.json_path, io::solution_to_json(s, sol)); !st.ok()) {
      ctx.err << "kinestat: " << st.message() << "\n";
      return kExitBadInput;
    }
    if (!o.quiet) ctx.out << "\nJSON results: " << o.json_path << "\n";
  }
  if (!o.vtk_dir.empty()) {
    std::vector<std::string> written;
    if (Status st = io::write_vtk(s, sol, o.vtk_dir, o.basename, &written); !st.ok()) {
      ctx.err << "kinestat: " << st.message() << "\n";
      return kExitBadInput;
    }
    if (!o.quiet)
      for (const auto& f : written) ctx.out << "ParaView file: " << f << "\n";
  }
  return exit_code_for(sol.status);
}

}  // namespace kinestat::cli
