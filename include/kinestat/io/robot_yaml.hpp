// Robot description files (YAML, docs/robots.md; models/robots/): legs of joints and links drawn at
// the home posture, leg patterns, task coordinates, the default map region, and named parameters
// whose values every number may use (expressions by muParser). Read into a RobotDescription
// (mechanisms/robot_model.hpp) in SI and built into a checked RobotModel.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/robot_model.hpp"

namespace kinestat::io {

// A parameter value given from outside the file (a design sweep's `--param arm=300`), in the
// file's units; it replaces the file's value before the parameters after it are evaluated.
using ParamOverrides = std::vector<std::pair<std::string, double>>;

// kInvalidInput "FILE:LINE: ITEM: what; fix" for anything malformed, and for an override that
// names no parameter of the file.
StatusOr<mechanisms::RobotDescription> read_robot_description(const std::string& path,
                                                              const ParamOverrides& overrides = {});
// The same from the file's text; `display_name` names it in messages.
StatusOr<mechanisms::RobotDescription> read_robot_description_string(const std::string& text,
                                                                     const std::string& display_name,
                                                                     const ParamOverrides& overrides = {});
// read_robot_description, then mechanisms::make_robot_model (its checks: closure rank, counts).
StatusOr<mechanisms::RobotModel> read_robot_model(const std::string& path, const ParamOverrides& overrides = {});

// True when the YAML file has a top-level `robot:` key (a robot description, not a structure or
// VJM model); kInvalidInput when it cannot be read or parsed.
StatusOr<bool> is_robot_file(const std::string& path);

// The names and values (in the file's units, after evaluation) of a file's `params:` and the name
// of its length and force units ("mm", "N"), for design sweeps and reports.
struct RobotParams {
  std::vector<std::pair<std::string, double>> values;
  std::string length_unit, force_unit;
  double length_scale = 1.0;  // m per file length unit
};
StatusOr<RobotParams> read_robot_params(const std::string& path);

}  // namespace kinestat::io
