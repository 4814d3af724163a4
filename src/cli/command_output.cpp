#include "cli/command_output.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "kinestat/io/results_json.hpp"

namespace kinestat::cli {

const CLI::Validator& positive_number() {
  static const CLI::Validator v(
      [](const std::string& text) -> std::string {
        double x = 0.0;
        std::size_t used = 0;
        try {
          x = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used != text.size() || !std::isfinite(x) || !(x > 0.0))
          return fmt::format("'{}' is not a finite number above 0", text);
        return {};
      },
      "POSITIVE");
  return v;
}

void add_output_options(CLI::App& cmd, OutputOptions& o, const std::string& schema, const std::string& doc) {
  cmd.add_option("--json", o.json,
                 "write the results as JSON, SI units (schema: " + doc + ", " + schema +
                     ") to FILE, or to stdout with '-' (the report then goes to stderr)");
  cmd.add_flag("--quiet", o.quiet, "print no report and no progress (errors still go to stderr)");
}

Output::Output(Context& ctx, const OutputOptions& o) : ctx_(ctx), options_(o) {}

std::ostream& Output::report() {
  if (options_.quiet) return discard_;
  return options_.json == "-" ? ctx_.err : ctx_.out;
}

std::ostream& Output::progress() { return options_.quiet ? discard_ : ctx_.err; }

int Output::finish(const std::string& command, const Status& result) {
  if (!result.ok() && options_.quiet) return report_failure(ctx_, command, result);
  return exit_code_for(result);
}

Status Output::write_json(const nlohmann::json& j, int indent) {
  if (options_.json.empty()) return Status::Ok();
  if (options_.json == "-") {
    io::write_json(ctx_.out, j, indent);
    if (!ctx_.out.flush())
      return Status::Invalid("stdout: writing the JSON failed (a full disk or a closed pipe?); give --json FILE");
    return Status::Ok();
  }
  std::error_code ec;  // the folder may not exist yet; write_json names what still fails
  if (const auto parent = std::filesystem::path(options_.json).parent_path(); !parent.empty())
    std::filesystem::create_directories(parent, ec);
  return io::write_json(options_.json, j, indent);
}

StatusOr<mechanisms::RobotModel> load_robot_model(Context& ctx, const std::string& command, const std::string& path,
                                                  bool quiet, const io::ParamOverrides& overrides,
                                                  std::map<int, Mat6>* computed) {
  StatusOr<mechanisms::RobotDescription> d = io::read_robot_description(path, overrides);
  if (!d.ok()) return d.status();
  auto each_fea = [&](auto f) {
    for (mechanisms::RobotLeg& leg : d->legs)
      for (auto& item : leg.items)
        if (auto* link = std::get_if<mechanisms::RobotLink>(&item); link && link->spring && link->spring->fea)
          f(*link->spring);
  };
  if (computed != nullptr)
    each_fea([&](mechanisms::RobotSpring& s) {
      if (const auto it = computed->find(s.fea_entry); it != computed->end()) s.stiffness = it->second;
    });
  auto progress = [&ctx, &command, quiet](const std::string& stage) {
    if (!quiet) ctx.err << command << ": " << stage << " ...\n";
  };
  // Warnings even when quiet: a cache entry was damaged and its result recomputed.
  auto warning = [&ctx, &command](const std::string& w) { ctx.err << command << ": warning: " << w << "\n"; };
  if (Status s = mechanisms::resolve_robot_fea_springs(*d, progress, warning); !s.ok()) return s;
  if (computed != nullptr)
    each_fea([&](const mechanisms::RobotSpring& s) { computed->emplace(s.fea_entry, s.stiffness); });
  return mechanisms::make_robot_model(std::move(*d));
}

}  // namespace kinestat::cli
