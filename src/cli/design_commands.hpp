// The parts of `kinestat design`: the robot-file sweep and the command itself (design_command.cpp),
// `design orthoglide` (design_orthoglide_command.cpp) and `design fivebar` (design_fivebar_command.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "cli/command_output.hpp"
#include "cli/grid_options.hpp"
#include "kinestat/cli/app.hpp"
#include "kinestat/core/status.hpp"
#include "kinestat/core/units.hpp"

namespace kinestat::cli {

// The subcommands `design orthoglide` and `design fivebar` of `design`.
void add_orthoglide_design(CLI::App* design, Context& ctx);
void add_five_bar_design(CLI::App* design, Context& ctx);

// A sweep's JSON and its timing, written through `out` (--json FILE or -); a file is added to
// `written` for the report's "wrote" lines. Ok without --json (the JSON is not made then).
Status write_sweep_json(Output& out, const OutputOptions& options, const std::function<nlohmann::json()>& make,
                        double seconds, std::size_t postures, int threads, std::vector<std::string>& written);

// The options every design sweep shares, checked, into its options `o`: --min-stiffness (N/mm, if
// given), --near-singular, --threads, --max-postures.
template <class SweepOptions>
Status set_sweep_options(const std::optional<double>& min_stiffness, double near_singular, int threads,
                         double max_postures, SweepOptions& o) {
  if (min_stiffness) {
    if (!(*min_stiffness >= 0.0 && std::isfinite(*min_stiffness)))
      return Status::Invalid(fmt::format("--min-stiffness {:g} N/mm: give a stiffness >= 0", *min_stiffness));
    o.min_stiffness = *min_stiffness / units::kMm;  // N/mm -> N/m
  }
  if (!(near_singular >= 0.0 && near_singular <= 1.0))
    return Status::Invalid(fmt::format("--near-singular {:g}: the threshold is in [0, 1]", near_singular));
  o.near_singular_threshold = near_singular;
  if (Status st = check_threads_option(threads); !st.ok()) return st;
  o.threads = threads;
  o.max_postures = max_postures;
  return Status::Ok();
}

}  // namespace kinestat::cli
