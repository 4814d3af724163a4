// What every command shares: --json FILE (or - for stdout) and --quiet, and where its report,
// progress and JSON go. With `--json -` stdout carries the JSON and nothing else: the report goes
// to stderr (or nowhere with --quiet).
#pragma once

#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "kinestat/cli/app.hpp"

namespace kinestat::cli {

struct OutputOptions {
  std::string json;    // empty: no JSON; "-": stdout
  bool quiet = false;  // no report and no progress (errors still go to stderr)
};

// Adds --json and --quiet; `schema` names the JSON's section of docs/results-json.md.
void add_output_options(CLI::App& cmd, OutputOptions& o, const std::string& schema);

class Output {
 public:
  Output(Context& ctx, const OutputOptions& o);
  Output(const Output&) = delete;
  Output& operator=(const Output&) = delete;

  std::ostream& report();    // stdout; stderr when the JSON goes to stdout; nowhere with --quiet
  std::ostream& progress();  // stderr; nowhere with --quiet
  bool json_wanted() const { return !options_.json.empty(); }
  // To the --json file (its folder created) or to stdout; Ok without --json. kInvalidInput naming
  // the file when it cannot be written.
  Status write_json(const nlohmann::json& j);
  // The exit status of a computed result (0, or 3 for a singular one). A result that is not ok is
  // explained in the report; with --quiet, which drops the report, through report_failure instead.
  int finish(const std::string& command, const Status& result);

 private:
  Context& ctx_;
  OutputOptions options_;
  std::ostream discard_{nullptr};  // a stream without buffer drops what is written to it
};

}  // namespace kinestat::cli
