// kinestat buckling FILE [--case NAME | --case-index I] [--count N] [--vtk DIR] [--json FILE|-] [--quiet]
#include <algorithm>
#include <filesystem>
#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/msa_output.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/io/vtk_output.hpp"
#include "kinestat/msa/buckling.hpp"

namespace kinestat::cli {
namespace {

std::string report(const msa::Structure& s, const msa::BucklingResult& r) {
  std::string t = fmt::format("Linear buckling of load case '{}' (K phi = -lambda K_G phi, {} free dofs)\n",
                              r.load_case_name, r.num_free_dofs);
  std::size_t most = 0;
  for (std::size_t i = 1; i < r.axial_force.size(); ++i)
    if (r.axial_force[i] < r.axial_force[most]) most = i;
  t += fmt::format("Most compressed beam: '{}', N = {:.6g} N (axial forces: mean of the end forces, tension > 0)\n",
                   s.beams()[most].id, r.axial_force[most]);
  t += "Critical load factors lambda (critical loads = lambda x the load case's loads):\n";
  t += fmt::format("  {:>4}  {:>14}  {:>22}  {:>9}\n", "mode", "lambda (-)",
                   fmt::format("N_cr of '{}' (N)", s.beams()[most].id), "residual");
  for (std::size_t k = 0; k < r.modes.size(); ++k)
    t += fmt::format("  {:>4}  {:>14.8g}  {:>22.8g}  {:>9.1e}\n", k + 1, r.modes[k].load_factor,
                     r.modes[k].load_factor * r.axial_force[most], r.modes[k].residual);
  t += "Mode shapes (scaled to a largest translation of 1 m; translations m, rotations rad at that scale):\n";
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    t += fmt::format("  mode {} (lambda = {:.8g})\n", k + 1, r.modes[k].load_factor);
    t += mode_shape_table(s, r.modes[k].shape, false);
  }
  return t;
}

}  // namespace

void register_buckling_command(CLI::App& app, Context& ctx) {
  struct Args {
    std::string file, case_name, vtk_dir;
    int case_index = -1;
    int count = 3;
    OutputOptions out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "buckling",
      "linear buckling of a YAML structure file (docs/stability-and-modes.md): the smallest critical load "
      "factors of one load case and their mode shapes; report, JSON and VTK in SI units");
  cmd->add_option("file", args->file, "structure file (.yaml)")->required();
  auto* by_name = cmd->add_option("--case", args->case_name, "the load case, by name (default: the first)");
  cmd->add_option("--case-index", args->case_index, "the load case, by index from 0 (default: 0)")
      ->check(CLI::NonNegativeNumber)
      ->excludes(by_name);
  cmd->add_option("--count", args->count, "how many of the smallest load factors (1 to 100, default 3)")
      ->check(CLI::Range(1, 100));
  cmd->add_option("--vtk", args->vtk_dir, "write ParaView files (.vtu per mode + .pvd) into this folder");
  add_output_options(*cmd, args->out, "kinestat-buckling-results");
  cmd->callback([args, &ctx] {
    const MsaProgress progress(ctx, "buckling", args->out.quiet);
    progress.reading(args->file);
    auto s = io::read_structure_yaml(args->file);
    if (!s.ok()) {
      ctx.exit_code = report_failure(ctx, "buckling", s.status());
      return;
    }
    msa::BucklingOptions opt;
    opt.count = args->count;
    opt.load_case = std::max(args->case_index, 0);
    // Said here with the option's name (the library names only the index), as modes' --prestress-index.
    const int nc = static_cast<int>(s->load_cases().size());
    if (args->case_index >= nc && nc > 0) {
      ctx.exit_code = report_failure(
          ctx, "buckling",
          Status::Invalid(fmt::format("{}: --case-index {}: the file has {} load case{}; give an index from 0 to {}, "
                                      "or a case's name with --case",
                                      args->file, args->case_index, nc, nc == 1 ? "" : "s", nc - 1)));
      return;
    }
    if (!args->case_name.empty()) {
      const StatusOr<int> k = load_case_index(*s, args->file, args->case_name, "--case");
      if (!k.ok()) {
        ctx.exit_code = report_failure(ctx, "buckling", k.status());
        return;
      }
      opt.load_case = *k;
    }
    progress.set(*s, opt.solve);
    const msa::BucklingResult r = msa::buckling(*s, opt);
    if (!r.status.ok()) {
      ctx.exit_code = report_failure(ctx, "buckling", r.status);
      return;
    }
    std::vector<io::VtkModeShape> modes;
    for (std::size_t k = 0; k < r.modes.size(); ++k)
      modes.push_back(
          {fmt::format("buckling mode {}: lambda = {:.6g}", k + 1, r.modes[k].load_factor), r.modes[k].shape});
    ctx.exit_code = finish_mode_run(
        "buckling", *s, report(*s, r), [&] { return io::buckling_to_json(*s, r); }, modes, args->vtk_dir,
        std::filesystem::path(args->file).stem().string() + "_buckling", "m (scaled: largest translation 1 m), rad",
        args->out, r.status, ctx);
  });
}

}  // namespace kinestat::cli
