// What every MSA-based command does after solving: print the report, write JSON and VTK, and
// turn the solution's status into the exit code. Shared by `solve` and `fivebar`; the end of the
// eigenvalue commands (`buckling`, `modes`) too, with their load-case lookup and mode-shape tables,
// and the structure file that `solve` and `modes` read.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/command_output.hpp"
#include "kinestat/io/frame3dd.hpp"
#include "kinestat/io/vtk_output.hpp"
#include "kinestat/msa/static_analysis.hpp"

namespace kinestat::cli {

// The structure of `file` for solve and modes: a Frame3DD .3dd file read with `units` (FORCE-LENGTH,
// required: a .3dd file states none), its notes and analysis settings into `notes` and `analysis`;
// or a YAML structure file, which states its own units (`units` refused).
StatusOr<msa::Structure> read_structure_file(const std::string& file, const std::string& units,
                                             std::vector<std::string>& notes, io::Frame3ddAnalysis& analysis);
// Adds the `file` argument and --units that read_structure_file takes.
void add_structure_file_options(CLI::App& cmd, std::string& file, std::string& units);

// The stages of an MSA command (solve, buckling, modes) on stderr for a large structure, each with
// the seconds since the command started: the reading of a file of kProgressBytes or more (about a
// second of parsing), and from kProgressDofs dofs (about a second of solving) the library's stages
// (msa::SolveOptions::progress: assembly, factorization, ..., the eigensolver). Nothing with --quiet.
class MsaProgress {
 public:
  static constexpr int kProgressDofs = 50000;
  static constexpr std::uintmax_t kProgressBytes = 2000000;
  MsaProgress(Context& ctx, std::string command, bool quiet);
  // "kinestat COMMAND: reading FILE (24 MB) ..." for a large file.
  void reading(const std::string& file) const;
  // Sets `opt`'s progress to print the stages, for a large `s` (msa forwards the Cholesky's to it).
  void set(const msa::Structure& s, msa::SolveOptions& opt) const;

 private:
  Context& ctx_;
  std::string command_;
  bool quiet_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

struct MsaOutputOptions {
  OutputOptions out;     // --json, --quiet
  std::string vtk_dir;   // empty: no VTK
  std::string basename;  // of the .vtu/.pvd files
  int stations = 0;      // --stations: along-member results per beam in the JSON (0: none)
  // --max-stations: stations x beams x load cases above this are refused before the solve (~1.4 kB
  // of memory and 0.42 kB of JSON each, measured).
  double max_stations = 1e6;
};

// Adds --vtk, --json and --quiet to a command.
void add_msa_output_options(CLI::App& cmd, MsaOutputOptions& o);

// Returns the exit status: 0 solved, 3 singular (diagnosis printed; files still written so the free
// motions can be seen in ParaView), 2 invalid model or unwritable output, 1 internal failure.
// `extra` holds fields added to the JSON document (the five-bar's posture).
int finish_msa_run(const std::string& command, const msa::Structure& s, const msa::Solution& sol,
                   const MsaOutputOptions& o, Context& ctx, const nlohmann::json& extra = nlohmann::json::object());

// The index of the load case of `s` named `name`; kInvalidInput "FILE: no load case named 'X' (it
// has 'a', 'b'); give one of them to <option>" otherwise.
StatusOr<int> load_case_index(const msa::Structure& s, const std::string& file, const std::string& name,
                              const std::string& option);

// One mode shape in the report of `buckling` or `modes`: a line per node (ux uy uz rx ry rz), in
// fixed notation or, with `scientific`, in scientific notation; a model of more than 50 nodes gets
// a pointer to --json and --vtk instead.
std::string mode_shape_table(const msa::Structure& s, const std::vector<Vec6>& shape, bool scientific);

// The end of `buckling` and `modes`: the report, the JSON (`make_json` is called only when JSON is
// wanted) and, with `vtk_dir`, one .vtu per mode shape and a .pvd named BASENAME (the shapes in
// `shape_units`). Returns the exit status for `status`, or the first writing failure's.
int finish_mode_run(const std::string& command, const msa::Structure& s, const std::string& report,
                    const std::function<StatusOr<nlohmann::json>()>& make_json,
                    const std::vector<io::VtkModeShape>& modes, const std::string& vtk_dir, const std::string& basename,
                    const std::string& shape_units, const OutputOptions& o, const Status& status, Context& ctx);

}  // namespace kinestat::cli
