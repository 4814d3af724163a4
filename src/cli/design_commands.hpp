// The parts of `kinestat design`: the robot-file sweep and the command itself (design_command.cpp),
// `design orthoglide` (design_orthoglide_command.cpp) and `design fivebar` (design_fivebar_command.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "kinestat/cli/app.hpp"
#include "kinestat/core/status.hpp"

namespace kinestat::cli {

// The subcommands `design orthoglide` and `design fivebar` of `design`.
void add_orthoglide_design(CLI::App* design, Context& ctx);
void add_five_bar_design(CLI::App* design, Context& ctx);

// A sweep's JSON with its timing: on stdout for "-" (nothing else goes there), else into `path`,
// added to `written`.
Status write_sweep_json(nlohmann::json j, const std::string& path, double seconds, std::size_t postures, int threads,
                        Context& ctx, std::vector<std::string>& written);

}  // namespace kinestat::cli
