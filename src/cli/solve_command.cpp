// kinestat solve FILE [--units FORCE-LENGTH] [--vtk DIR] [--json FILE|-] [--stations N] [--quiet] [--regularize]
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>

#include <CLI/CLI.hpp>

#include "cli/msa_output.hpp"
#include "kinestat/io/frame3dd.hpp"
#include "kinestat/io/structure_yaml.hpp"

namespace kinestat::cli {
namespace {

bool is_frame3dd(const std::string& file) {
  std::string ext = std::filesystem::path(file).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".3dd";
}

}  // namespace

void register_solve_command(CLI::App& app, Context& ctx) {
  struct Args {
    std::string file;
    std::string units;
    bool regularize = false;
    MsaOutputOptions out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "solve", "solve a YAML structure file (format: docs/structure-format.md; its numbers are in the file's "
               "'units:') or a Frame3DD .3dd file (with --units); the report, JSON and VTK are in SI units");
  cmd->add_option("file", args->file, "structure file (.yaml) or Frame3DD input file (.3dd)")->required();
  cmd->add_option("--units", args->units,
                  "FORCE-LENGTH of a .3dd file, which states none (required there, refused for YAML): force N, kN, "
                  "lbf or kip, length m, mm, cm, in or ft, e.g. kip-in or N-mm");
  cmd->add_flag("--regularize", args->regularize,
                "for a singular structure, also print a REGULARIZED answer (K + 1e-10 diag K), clearly marked");
  add_msa_output_options(*cmd, args->out);
  cmd->add_option("--stations", args->out.stations,
                  "with --json: internal forces (N, Vy, Vz, T, My, Mz) and local displacements at N equally spaced "
                  "stations along every beam, with their extremes (2 to 10000)")
      ->check(CLI::Range(2, 10000));
  cmd->callback([args, &ctx] {
    const bool frame3dd = is_frame3dd(args->file);
    StatusOr<msa::Structure> s = Status::Invalid("");
    std::vector<std::string> notes;
    if (frame3dd) {
      if (args->units.empty()) {
        ctx.exit_code = report_failure(
            ctx, "solve",
            Status::Invalid(args->file + ": a .3dd file states no units; give them with --units FORCE-LENGTH, e.g. "
                                         "--units kip-in or --units N-mm"));
        return;
      }
      const StatusOr<io::FileUnits> units = io::units_from_name(args->units, "--units");
      if (!units.ok()) {
        ctx.exit_code = report_failure(ctx, "solve", units.status());
        return;
      }
      s = io::read_frame3dd(args->file, *units, &notes);
    } else {
      if (!args->units.empty()) {
        ctx.exit_code = report_failure(
            ctx, "solve",
            Status::Invalid("--units is for Frame3DD .3dd files; a YAML structure file states its units in its "
                            "'units:' key (docs/structure-format.md); remove --units"));
        return;
      }
      s = io::read_structure_yaml(args->file);
    }
    if (!s.ok()) {
      ctx.exit_code = report_failure(ctx, "solve", s.status());
      return;
    }
    if (!args->out.out.quiet)
      for (const std::string& note : notes) ctx.err << "kinestat solve: note: " << note << "\n";
    msa::SolveOptions opt;
    opt.regularize = args->regularize;
    const msa::Solution sol = msa::solve(*s, opt);
    args->out.basename = std::filesystem::path(args->file).stem().string();
    ctx.exit_code = finish_msa_run("solve", *s, sol, args->out, ctx);
  });
}

}  // namespace kinestat::cli
