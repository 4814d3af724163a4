// kinestat solve FILE [--units FORCE-LENGTH] [--second-order [--tolerance T] [--max-iterations N]] [--vtk DIR]
//                     [--json FILE|-] [--stations N [--max-stations M]] [--quiet] [--regularize]
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/msa_output.hpp"
#include "kinestat/core/input_checks.hpp"
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
  cmd->add_option("--max-stations", args->out.max_stations,
                  "refuse --stations whose total over beams and load cases is above this (default 1000000: ~1.4 GB "
                  "of memory, 0.42 GB of JSON)")
      ->check(positive_number());
  cmd->callback([args, cmd, &ctx] {
    // A large structure's solve takes seconds to minutes (540 000 dofs, 24 MB of YAML: 13 s of
    // reading and 100 s of solving on 2 cores, mostly the factorization): its stages on stderr.
    const MsaProgress progress(ctx, "solve", args->out.out.quiet);
    std::vector<std::string> notes;
    io::Frame3ddAnalysis analysis;
    progress.reading(args->file);
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
    // The stations are held in memory and then in the JSON document (both measured: ~1.4 kB of memory
    // and 0.42 kB of JSON per station): 2700 beams at --stations 10000 grew past 23 GB before.
    if (args->out.stations > 0) {
      const double beams = static_cast<double>(s->beams().size()), cases = static_cast<double>(s->load_cases().size());
      const double total = beams * cases * args->out.stations;
      const double fits = std::floor(args->out.max_stations / std::max(1.0, beams * cases));
      const std::string advice =
          fits >= 2 ? fmt::format("give a smaller --stations (at most {:.0f} here), or raise --max-stations", fits)
                    : std::string("raise --max-stations, or solve without --stations and divide the beams instead");
      if (Status st = check_size(
              total, args->out.max_stations,
              fmt::format("--stations {}: {:.0f} beam{} x {:.0f} load case{} x {} stations", args->out.stations, beams,
                          beams == 1 ? "" : "s", cases, cases == 1 ? "" : "s", args->out.stations),
              fmt::format("stations (~{:.2g} GB of memory, {:.2g} GB of JSON)", total * 1.4e3 * 1e-9,
                          total * 0.42e3 * 1e-9),
              advice);
          !st.ok()) {
        ctx.exit_code = report_failure(ctx, "solve", st);
        return;
      }
    }
    msa::SolveOptions opt;
    opt.regularize = args->regularize;
    progress.set(*s, opt);
    const msa::Solution sol = args->second_order ? msa::solve_second_order(*s, args->second, opt) : msa::solve(*s, opt);
    args->out.basename = std::filesystem::path(args->file).stem().string();
    ctx.exit_code = finish_msa_run("solve", *s, sol, args->out, ctx);
  });
}

}  // namespace kinestat::cli
