#include "cli/msa_output.hpp"

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <utility>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "kinestat/io/results_json.hpp"
#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/io/vtk_output.hpp"

namespace kinestat::cli {

MsaProgress::MsaProgress(Context& ctx, std::string command, bool quiet)
    : ctx_(ctx), command_(std::move(command)), quiet_(quiet) {}

void MsaProgress::reading(const std::string& file) const {
  std::error_code error;
  const std::uintmax_t bytes = std::filesystem::file_size(file, error);
  if (!quiet_ && !error && bytes >= kProgressBytes)
    ctx_.err << fmt::format("kinestat {}: reading {} ({:.0f} MB) ...\n", command_, file, bytes * 1e-6) << std::flush;
}

void MsaProgress::set(const msa::Structure& s, msa::SolveOptions& opt) const {
  if (quiet_ || s.num_dofs() < kProgressDofs) return;
  opt.progress = [&ctx = ctx_, command = command_, start = start_](const std::string& stage) {
    const std::chrono::duration<double> t = std::chrono::steady_clock::now() - start;
    ctx.err << fmt::format("kinestat {}: {} ... ({:.1f} s)\n", command, stage, t.count()) << std::flush;
  };
}

StatusOr<msa::Structure> read_structure_file(const std::string& file, const std::string& units,
                                             std::vector<std::string>& notes, io::Frame3ddAnalysis& analysis) {
  if (!io::is_frame3dd_file(file)) {
    if (!units.empty())
      return Status::Invalid(
          "--units is for Frame3DD .3dd files; a YAML structure file states its units in its "
          "'units:' key (docs/structure-format.md); remove --units");
    return io::read_structure_yaml(file);
  }
  if (units.empty())
    return Status::Invalid(file +
                           ": a .3dd file states no units; give them with --units FORCE-LENGTH, e.g. "
                           "--units kip-in or --units N-mm");
  const StatusOr<io::FileUnits> u = io::units_from_name(units, "--units");
  if (!u.ok()) return u.status();
  return io::read_frame3dd(file, *u, &notes, &analysis);
}

void add_structure_file_options(CLI::App& cmd, std::string& file, std::string& units) {
  cmd.add_option("file", file, "structure file (.yaml) or Frame3DD input file (.3dd)")->required();
  cmd.add_option("--units", units,
                 "FORCE-LENGTH of a .3dd file, which states none (required there, refused for YAML): force N, kN, "
                 "lbf or kip, length m, mm, cm, in or ft, e.g. kip-in or N-mm");
}

void add_msa_output_options(CLI::App& cmd, MsaOutputOptions& o) {
  cmd.add_option("--vtk", o.vtk_dir, "write ParaView files (.vtu per load case + .pvd, SI units) into this folder");
  add_output_options(cmd, o.out, "kinestat-msa-results");
}

int finish_msa_run(const std::string& command, const msa::Structure& s, const msa::Solution& sol,
                   const MsaOutputOptions& o, Context& ctx, const nlohmann::json& extra) {
  const StatusCode code = sol.status.code();
  if (code == StatusCode::kInvalidInput || code == StatusCode::kInternal)
    return report_failure(ctx, command, sol.status);
  StatusOr<std::string> report = msa::full_report(s, sol);
  if (!report.ok()) return report_failure(ctx, command, report.status());
  Output out(ctx, o.out);
  out.report() << *report;
  // The stations, for the JSON and the VTK diagrams.
  std::vector<std::vector<msa::BeamStations>> stations;
  if (o.stations > 0 && !sol.cases.empty()) {
    auto st = msa::all_beam_stations(s, sol, o.stations);
    if (!st.ok()) return report_failure(ctx, command, st.status());
    stations = std::move(*st);
  }
  if (out.json_wanted()) {
    StatusOr<nlohmann::json> j = io::solution_to_json(s, sol, o.stations > 0 ? &stations : nullptr);
    if (!j.ok()) return report_failure(ctx, command, j.status());
    j->update(extra);
    if (Status st = out.write_json(*j); !st.ok()) return report_failure(ctx, command, st);
    if (o.out.json != "-") out.report() << "\nJSON results: " << o.out.json << "\n";
  }
  if (!o.vtk_dir.empty()) {
    std::vector<std::string> written;
    if (Status st = io::write_vtk(s, sol, o.vtk_dir, o.basename, &written); !st.ok())
      return report_failure(ctx, command, st);
    if (!stations.empty())
      if (Status st = io::write_beam_diagrams_vtk(s, sol, stations, o.vtk_dir, o.basename, &written); !st.ok())
        return report_failure(ctx, command, st);
    for (const auto& f : written) out.report() << "ParaView file: " << f << "\n";
  }
  return out.finish(command, sol.status);
}

StatusOr<int> load_case_index(const msa::Structure& s, const std::string& file, const std::string& name,
                              const std::string& option) {
  const auto& cases = s.load_cases();
  const auto it = std::find_if(cases.begin(), cases.end(), [&](const msa::LoadCase& c) { return c.name == name; });
  if (it != cases.end()) return static_cast<int>(it - cases.begin());
  std::string names;
  for (const auto& c : cases) names += (names.empty() ? "'" : ", '") + c.name + "'";
  return Status::Invalid(fmt::format("{}: no load case named '{}' (it has {}); give one of them to {}", file, name,
                                     names.empty() ? "none" : names, option));
}

std::string mode_shape_table(const msa::Structure& s, const std::vector<Vec6>& shape, bool scientific) {
  constexpr std::size_t kMaxPrintedNodes = 50;  // larger models: --json or --vtk
  if (s.nodes().size() > kMaxPrintedNodes)
    return fmt::format("    ({} nodes: see --json or --vtk)\n", s.nodes().size());
  const int w = scientific ? 11 : 10;  // "-1.2345e-03" is one wider than the fixed "-123.4567"
  std::string t = fmt::format("    {:>10} {:>{}} {:>{}} {:>{}} {:>{}} {:>{}} {:>{}}\n", "node", "ux", w, "uy", w, "uz",
                              w, "rx", w, "ry", w, "rz", w);
  for (std::size_t n = 0; n < s.nodes().size(); ++n) {
    t += fmt::format("    {:>10}", s.nodes()[n].id);
    for (int d = 0; d < 6; ++d)
      t += scientific ? fmt::format(" {:>11.4e}", shape[n](d)) : fmt::format(" {:>10.4f}", shape[n](d));
    t += "\n";
  }
  return t;
}

int finish_mode_run(const std::string& command, const msa::Structure& s, const std::string& report,
                    const std::function<StatusOr<nlohmann::json>()>& make_json,
                    const std::vector<io::VtkModeShape>& modes, const std::string& vtk_dir, const std::string& basename,
                    const std::string& shape_units, const OutputOptions& o, const Status& status, Context& ctx) {
  Output out(ctx, o);
  out.report() << report;
  if (out.json_wanted()) {
    StatusOr<nlohmann::json> j = make_json();
    if (!j.ok()) return report_failure(ctx, command, j.status());
    if (Status st = out.write_json(*j); !st.ok()) return report_failure(ctx, command, st);
    if (o.json != "-") out.report() << "JSON results: " << o.json << "\n";
  }
  if (!vtk_dir.empty()) {
    std::vector<std::string> written;
    if (Status st = io::write_mode_shapes_vtk(s, modes, vtk_dir, basename, shape_units, &written); !st.ok())
      return report_failure(ctx, command, st);
    for (const auto& f : written) out.report() << "ParaView file: " << f << "\n";
  }
  return out.finish(command, status);
}

}  // namespace kinestat::cli
