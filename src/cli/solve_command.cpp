// kinestat solve FILE [--vtk DIR] [--json FILE|-] [--stations N] [--quiet] [--regularize]
#include <filesystem>
#include <ostream>

#include <CLI/CLI.hpp>

#include "cli/msa_output.hpp"
#include "kinestat/io/structure_yaml.hpp"

namespace kinestat::cli {

void register_solve_command(CLI::App& app, Context& ctx) {
  struct Args {
    std::string file;
    bool regularize = false;
    MsaOutputOptions out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "solve", "solve a YAML structure file (format: docs/structure-format.md; its numbers are in the file's "
               "'units:', SI or mm-N-s); the report, JSON and VTK are in SI units");
  cmd->add_option("file", args->file, "structure file (.yaml)")->required();
  cmd->add_flag("--regularize", args->regularize,
                "for a singular structure, also print a REGULARIZED answer (K + 1e-10 diag K), clearly marked");
  add_msa_output_options(*cmd, args->out);
  cmd->add_option("--stations", args->out.stations,
                  "with --json: internal forces (N, Vy, Vz, T, My, Mz) and local displacements at N equally spaced "
                  "stations along every beam, with their extremes (2 to 10000)")
      ->check(CLI::Range(2, 10000));
  cmd->callback([args, &ctx] {
    auto s = io::read_structure_yaml(args->file);
    if (!s.ok()) {
      ctx.exit_code = report_failure(ctx, "solve", s.status());
      return;
    }
    msa::SolveOptions opt;
    opt.regularize = args->regularize;
    const msa::Solution sol = msa::solve(*s, opt);
    args->out.basename = std::filesystem::path(args->file).stem().string();
    ctx.exit_code = finish_msa_run("solve", *s, sol, args->out, ctx);
  });
}

}  // namespace kinestat::cli
