// kinestat solve FILE [--units FORCE-LENGTH] [--second-order [--tolerance T] [--max-iterations N]] [--vtk DIR]
//                     [--json FILE|-] [--stations N] [--quiet] [--regularize]
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/msa_output.hpp"
#include "kinestat/io/frame3dd.hpp"
#include "kinestat/io/structure_yaml.hpp"

namespace kinestat::cli {
void register_solve_command(CLI::App& app, Context& ctx) {
  struct Args {
    std::string file;
    std::string units;
    bool regularize = false;
    bool second_order = false;
    msa::SecondOrderOptions second;
    MsaOutputOptions out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd =
      app.add_subcommand("solve",
                         "solve a YAML structure file (format: docs/structure-format.md; its numbers are in the file's "
                         "'units:') or a Frame3DD .3dd file (with --units); the report, JSON and VTK are in SI units");
  add_structure_file_options(*cmd, args->file, args->units);
  cmd->add_flag("--regularize", args->regularize,
                "for a singular structure, also print a REGULARIZED answer (K + 1e-10 diag K), clearly marked");
  cmd->add_flag("--second-order", args->second_order,
                "second-order (P-Delta) analysis: the beams' axial forces soften or stiffen them through the geometric "
                "stiffness, iterated to convergence (docs/stability-and-modes.md); a .3dd file with its geometric "
                "stiffness flag 1 is solved so without it");
  cmd->add_option("--tolerance", args->second.tolerance,
                  "with --second-order: relative change of the displacements that ends the iterations "
                  "(dimensionless, default 1e-9)");
  cmd->add_option("--max-iterations", args->second.max_iterations,
                  "with --second-order: most solves of K + K_G(N) per load case (count, default 50)");
  add_msa_output_options(*cmd, args->out);
  cmd->add_option("--stations", args->out.stations,
                  "with --json: internal forces (N, Vy, Vz, T, My, Mz) and local displacements at N equally spaced "
                  "stations along every beam, with their extremes (2 to 10000)")
      ->check(CLI::Range(2, 10000));
  cmd->callback([args, cmd, &ctx] {
    std::vector<std::string> notes;
    io::Frame3ddAnalysis analysis;
    StatusOr<msa::Structure> s = read_structure_file(args->file, args->units, notes, analysis);
    if (s.ok() && analysis.modes > 0)
      notes.push_back(
          fmt::format("{}: {} dynamic modes asked for: kinestat solve is static and computes none; "
                      "kinestat modes computes them with the file's modal data",
                      analysis.modes_source, analysis.modes));
    // Frame3DD's geometric stiffness flag asks for its second-order analysis: honoured, said.
    if (s.ok() && analysis.geometric_stiffness && !args->second_order) {
      args->second_order = true;
      notes.push_back(analysis.geometric_stiffness_source +
                      ": geometric stiffness flag 1: solved as a second-order (P-Delta) analysis, as --second-order "
                      "does (write 0 there for a linear one)");
    }
    if (!s.ok()) {
      ctx.exit_code = report_failure(ctx, "solve", s.status());
      return;
    }
    if (!args->out.out.quiet)
      for (const std::string& note : notes) ctx.err << "kinestat solve: note: " << note << "\n";
    auto refuse = [&](const std::string& m) { ctx.exit_code = report_failure(ctx, "solve", Status::Invalid(m)); };
    if (!args->second_order && (cmd->count("--tolerance") > 0 || cmd->count("--max-iterations") > 0))
      return refuse(
          "--tolerance and --max-iterations set the second-order iteration: add --second-order, or remove "
          "them");
    if (args->second_order && args->regularize)
      return refuse(
          "--regularize and --second-order do not go together: a singular structure has no axial forces "
          "to iterate on; solve it without --second-order");
    // Along a member in second order the moment gains N times the deflection from the chord, which the
    // stations' linear equilibrium of [0, x] does not hold: no numbers rather than wrong ones.
    if (args->second_order && args->out.stations > 0)
      return refuse(
          "--stations is not available with --second-order: the along-member forces would miss the axial "
          "force's moment on the member's own deflection; divide the members into more beams and read "
          "their end forces instead");
    msa::SolveOptions opt;
    opt.regularize = args->regularize;
    const msa::Solution sol = args->second_order ? msa::solve_second_order(*s, args->second, opt) : msa::solve(*s, opt);
    args->out.basename = std::filesystem::path(args->file).stem().string();
    ctx.exit_code = finish_msa_run("solve", *s, sol, args->out, ctx);
  });
}

}  // namespace kinestat::cli
