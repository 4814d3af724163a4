// Reading the compliance targets of an identification (mechanisms/orthoglide_identification.hpp)
// from a YAML file: `kinestat identify MODEL TARGETS`. Format (docs/vjm.md, "Identifying inputs"):
//
//   units: mm-N-s        # or SI. Compliance: mm/N (translation rows and columns), rad/(N mm)
//                        # (rotation), 1/N (coupling); points in mm (kinematics frame)
//   inputs: [actuator_stiffness, bar_scale, parallelogram_width, platform_offset, foot_length]
//   targets:
//     - {label: "Q0 k_tran", architecture: 3-PUU, point: [0, 0, 0], row: 0, col: 0, value: 2.78e-4}
//
// Rows and columns are the dofs (dx dy dz rx ry rz) of C = K^-1 at the tool point, 0-based.
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/orthoglide_identification.hpp"

namespace kinestat::io {

struct IdentificationTargets {
  std::vector<mechanisms::OrthoglideInput> inputs;
  std::vector<mechanisms::ComplianceTarget> targets;  // SI
};

// Problems give kInvalidInput "FILE:LINE: ITEM: what is wrong; what to do".
StatusOr<IdentificationTargets> read_identification_targets_yaml(const std::string& path);
StatusOr<IdentificationTargets> read_identification_targets_yaml_string(const std::string& text,
                                                                        const std::string& display_name);

// The file's name of an input (`actuator_stiffness`, ...).
const char* input_key(mechanisms::OrthoglideInput input);

}  // namespace kinestat::io
