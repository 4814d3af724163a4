// What every command shares: --json FILE (or - for stdout) and --quiet, and where its report,
// progress and JSON go. With `--json -` stdout carries the JSON and nothing else: the report goes
// to stderr (or nowhere with --quiet).
#pragma once

#include <map>
#include <ostream>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "kinestat/cli/app.hpp"
#include "kinestat/io/robot_yaml.hpp"
#include "kinestat/mechanisms/robot_model.hpp"

namespace kinestat::cli {

struct OutputOptions {
  std::string json;    // empty: no JSON; "-": stdout
  bool quiet = false;  // no report and no progress (errors still go to stderr)
};

// A check for options that count or bound something: a finite number above 0. (CLI::PositiveNumber
// lets NaN through and prints its upper bound, DBL_MAX, in 309 digits.)
const CLI::Validator& positive_number();

// Adds --json and --quiet; `schema` names the JSON's section of `doc`.
void add_output_options(CLI::App& cmd, OutputOptions& o, const std::string& schema,
                        const std::string& doc = "docs/results-json.md");

class Output {
 public:
  Output(Context& ctx, const OutputOptions& o);
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  std::ostream& report();    // stdout; stderr when the JSON goes to stdout; nowhere with --quiet
  std::ostream& progress();  // stderr; nowhere with --quiet
  bool json_wanted() const { return !options_.json.empty(); }
  // To the --json file (its folder created; written atomically, io::write_json) or to stdout,
  // indented by `indent` spaces (-1: compact); Ok without --json. kInvalidInput naming the file
  // when it cannot be written.
  Status write_json(const nlohmann::json& j, int indent = 2);
  // The exit status of a computed result (0, or 3 for a singular one). A result that is not ok is
  // explained in the report; with --quiet, which drops the report, through report_failure instead.
  int finish(const std::string& command, const Status& result);

 private:
  Context& ctx_;
  OutputOptions options_;
  std::ostream discard_{nullptr};  // a stream without buffer drops what is written to it
};

// A robot file (docs/robots.md) read, its links' `fea:` springs computed (meshing and FEA or their
// cache: progress "COMMAND: stage ..." on ctx.err unless `quiet`, warnings always), and built by
// make_robot_model. `computed` (optional) keeps the springs by file entry across calls: a design
// sweep's designs re-read the file, and its `fea:` blocks take no parameters.
StatusOr<mechanisms::RobotModel> load_robot_model(Context& ctx, const std::string& command, const std::string& path,
                                                  bool quiet, const io::ParamOverrides& overrides = {},
                                                  std::map<int, Mat6>* computed = nullptr);

}  // namespace kinestat::cli
