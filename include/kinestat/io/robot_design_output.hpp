// Design sweeps of robot files (mechanisms/robot_design_sweep.hpp) as files: JSON and VTK ImageData.
//
// JSON, schema "kinestat-robot-design-sweep" (docs/maps.md, "Design sweep of a robot file"):
//   robot, description; parameters: [{name, lo, hi, values}] in `parameter_units`; designs: count,
//   dimensions (first parameter fastest); region: the grid of postures (m); criteria:
//   near_singular_threshold, min_stiffness (N/m); measure_unit (m^2 or m^3);
//   designs_table: per design {index, values, status ("ok" or "failed"), message, reachable_measure,
//   stiff_measure, reachable_points, stiff_points, k_t_min_worst (N/m, null: none)};
//   best: the same for the best design plus its parameters by name; ranks (MPI).
// VTI (one to three parameters): the design grid, x, y, z the parameters in their units, one cell per
// design, cell arrays stiff_measure (active), reachable_measure (m^2 or m^3), failed (1 or 0).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/robot_design_sweep.hpp"

namespace kinestat::io {

// `robot` names the file, `parameter_units` says what unit the parameters are in ("the file's units,
// mm-N-s: lengths in mm").
nlohmann::json robot_design_sweep_to_json(const mechanisms::RobotDesignSweep& sweep, const std::string& robot,
                                          const std::string& parameter_units);

// kInvalidInput naming the path when it cannot be written, or when the sweep has more than three
// parameters (an image has three axes).
Status write_robot_design_sweep_vti(const std::string& path, const mechanisms::RobotDesignSweep& sweep,
                                    const std::string& parameter_units);

}  // namespace kinestat::io
