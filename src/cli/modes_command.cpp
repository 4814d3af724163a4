// kinestat modes FILE [--units FORCE-LENGTH] [--count N] [--lumped] [--prestress CASE|none | --prestress-index I]
//                     [--second-order] [--vtk DIR] [--json FILE|-] [--quiet]
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <ostream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "cli/msa_output.hpp"
#include "kinestat/io/frame3dd.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/io/vtk_output.hpp"
#include "kinestat/msa/modes.hpp"

namespace kinestat::cli {
namespace {

std::string report(const msa::Structure& s, const msa::ModalResult& r, bool lumped) {
  std::string t;
  if (r.prestress)
    t = fmt::format(
        "Natural frequencies of the structure prestressed by load case '{}' ((K + K_G) phi = omega^2 M phi, "
        "K_G of its {} axial forces, {} beam masses, {} free dofs)\n",
        r.prestress->load_case_name, r.prestress->second_order ? "second-order" : "linear",
        lumped ? "lumped" : "consistent", r.num_free_dofs);
  else
    t = fmt::format(
        "Natural frequencies of the unstressed structure (K phi = omega^2 M phi, {} beam masses, {} free "
        "dofs)\n",
        lumped ? "lumped" : "consistent", r.num_free_dofs);
  t += fmt::format("Total mass: {:.6g} kg (x), {:.6g} kg (y), {:.6g} kg (z)\n", r.total_mass(0), r.total_mass(1),
                   r.total_mass(2));
  t += fmt::format("  {:>4}  {:>14}  {:>14}  {:>26}  {:>9}\n", "mode", "f (Hz)", "omega (rad/s)",
                   "effective mass x, y, z (%)", "residual");
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const auto& m = r.modes[k];
    Vec3 pct = Vec3::Zero();
    for (int d = 0; d < 3; ++d) pct(d) = r.total_mass(d) > 0 ? 100 * m.effective_mass(d) / r.total_mass(d) : 0.0;
    t += fmt::format("  {:>4}  {:>14.8g}  {:>14.8g}  {:>8.3f} {:>8.3f} {:>8.3f}  {:>9.1e}\n", k + 1, m.frequency,
                     m.omega, pct(0), pct(1), pct(2), m.residual);
  }
  t += "Mode shapes (mass-normalized, phi' M phi = 1: translations m/sqrt(kg), rotations rad/sqrt(kg)):\n";
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    t += fmt::format("  mode {} (f = {:.8g} Hz)\n", k + 1, r.modes[k].frequency);
    t += mode_shape_table(s, r.modes[k].shape, true);
  }
  return t;
}

}  // namespace

void register_modes_command(CLI::App& app, Context& ctx) {
  struct Args {
    std::string file, vtk_dir, units, prestress;
    int count = 6, prestress_index = -1;
    bool lumped = false, second_order = false;
    OutputOptions out;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "modes",
      "natural frequencies and mode shapes of a YAML structure file or a Frame3DD .3dd file (with --units; "
      "docs/stability-and-modes.md; materials need a density); report, JSON and VTK in SI units");
  add_structure_file_options(*cmd, args->file, args->units);
  cmd->add_option("--count", args->count,
                  "how many of the lowest frequencies (1 to 100, default 6, or a .3dd file's number of modes)")
      ->check(CLI::Range(1, 100));
  cmd->add_flag("--lumped", args->lumped,
                "lumped beam masses instead of consistent ones (a .3dd file's lumped flag 1 "
                "asks for them too)");
  auto* by_name = cmd->add_option(
      "--prestress", args->prestress,
      "the load case whose axial forces prestress the structure (K + K_G), by name (a .3dd file's cases are 'case 1', "
      "'case 2', ...), or 'none' for the unstressed structure (default: none; a .3dd file with geometric stiffness "
      "flag 1: its last case, as Frame3DD)");
  cmd->add_option("--prestress-index", args->prestress_index,
                  "the prestressing load case by index from 0 (as buckling's --case-index)")
      ->check(CLI::NonNegativeNumber)
      ->excludes(by_name);
  cmd->add_flag("--second-order", args->second_order,
                "the prestress's axial forces from the second-order (P-Delta) solve (a .3dd file's geometric "
                "stiffness flag 1 asks for it too)");
  cmd->add_option("--vtk", args->vtk_dir, "write ParaView files (.vtu per mode + .pvd) into this folder");
  add_output_options(*cmd, args->out, "kinestat-modes-results");
  cmd->callback([args, cmd, &ctx] {
    auto fail = [&](const Status& st) { ctx.exit_code = report_failure(ctx, "modes", st); };
    const MsaProgress progress(ctx, "modes", args->out.quiet);
    std::vector<std::string> notes;
    io::Frame3ddAnalysis analysis;
    progress.reading(args->file);
    const StatusOr<msa::Structure> s = read_structure_file(args->file, args->units, notes, analysis);
    if (!s.ok()) return fail(s.status());
    const auto& cases = s->load_cases();
    const int nc = static_cast<int>(cases.size());
    // The prestressing case: -1 none; by name or index as `kinestat buckling` selects its case.
    int prestress = -1;
    const bool asked_none = args->prestress == "none";
    if (args->prestress_index >= 0) {
      if (args->prestress_index >= nc)
        return fail(
            Status::Invalid(fmt::format("{}: --prestress-index {}: the file has {} load case{}{}; give an index "
                                        "from 0 to {}",
                                        args->file, args->prestress_index, nc, nc == 1 ? "" : "s",
                                        nc == 0 ? " (none to prestress it)" : "", nc - 1)));
      prestress = args->prestress_index;
    } else if (!args->prestress.empty() && !asked_none) {
      const StatusOr<int> k = load_case_index(*s, args->file, args->prestress, "--prestress, or 'none'");
      if (!k.ok()) return fail(k.status());
      prestress = *k;
    }
    bool second_order = args->second_order;
    if (io::is_frame3dd_file(args->file)) {
      // The file's modal data: its number of modes and mass matrix unless the options say otherwise.
      if (analysis.modes > 0 && cmd->count("--count") == 0) {
        if (analysis.modes > 100)
          return fail(
              Status::Invalid(fmt::format("{}: {} dynamic modes: kinestat modes computes 1 to 100; write "
                                          "fewer there, or give --count",
                                          analysis.modes_source, analysis.modes)));
        args->count = analysis.modes;
      }
      if (analysis.lumped && !args->lumped) {
        args->lumped = true;
        notes.push_back(analysis.lumped_source +
                        ": lumped mass flag 1: kinestat's lumped beam masses (no rotary "
                        "inertia of the bending rotations, unlike Frame3DD's)");
      }
      // Frame3DD's modal analysis takes the stiffness its static analysis leaves, which with this flag
      // holds the geometric stiffness of the last load case's second-order axial forces: its
      // frequencies are those of the structure prestressed by that case, and so are these by default.
      if (analysis.geometric_stiffness) {
        second_order = true;
        if (asked_none)
          notes.push_back(analysis.geometric_stiffness_source +
                          ": geometric stiffness flag 1, but --prestress none: the unstressed structure's frequencies "
                          "(Frame3DD's are prestressed by its last load case)");
        else if (prestress < 0 && nc > 0) {
          prestress = nc - 1;
          notes.push_back(analysis.geometric_stiffness_source +
                          fmt::format(": geometric stiffness flag 1: as Frame3DD, the frequencies of the structure "
                                      "prestressed by its last load case, '{}' (K + K_G of its second-order axial "
                                      "forces); --prestress none gives the unstressed structure's",
                                      cases[static_cast<std::size_t>(nc - 1)].name));
        }
      }
      if (analysis.modes == 0)
        notes.push_back(analysis.modes_source +
                        ": 0 dynamic modes and no modal data: beam masses from the densities, "
                        "count from --count");
    }
    if (!args->out.quiet)
      for (const std::string& note : notes) ctx.err << "kinestat modes: note: " << note << "\n";
    if (second_order && prestress < 0 && args->second_order)
      return fail(
          Status::Invalid("--second-order is for the prestress's axial forces: add --prestress CASE (or "
                          "--prestress-index I), or omit --second-order"));
    msa::ModalOptions opt;
    opt.count = args->count;
    opt.lumped = args->lumped;
    if (prestress >= 0) opt.prestress = msa::ModalPrestress{prestress, second_order, {}};
    progress.set(*s, opt.solve);
    const msa::ModalResult r = msa::modal_analysis(*s, opt);
    if (!r.status.ok()) return fail(r.status);
    std::vector<io::VtkModeShape> modes;
    for (std::size_t k = 0; k < r.modes.size(); ++k)
      modes.push_back({fmt::format("mode {}: f = {:.6g} Hz", k + 1, r.modes[k].frequency), r.modes[k].shape});
    ctx.exit_code = finish_mode_run(
        "modes", *s, report(*s, r, args->lumped), [&] { return io::modes_to_json(*s, r, args->lumped); }, modes,
        args->vtk_dir, std::filesystem::path(args->file).stem().string() + "_modes",
        "m/sqrt(kg), rad/sqrt(kg) (mass-normalized)", args->out, r.status, ctx);
  });
}

}  // namespace kinestat::cli
