// Five-bar design sweeps (mechanisms/five_bar_design_sweep.hpp) as files: JSON and VTK ImageData.
//
// JSON, schema "kinestat-five-bar-design-sweep" (docs/maps.md, "Design sweep"):
//   designs: grid of (r1, r2) (m; x: r1, y: r2, r1 fastest); region: the grid of postures (m)
//   criteria: near_singular_threshold, min_stiffness (N/m or null), their meaning
//   fields: flat arrays over the designs: r1, r2 (m), reachable_share, singularity_free_share,
//           share (of the region's points, 0..1), k_t_min_worst (N/m, null: none); units per field
//   best: index, r1, r2 (m), k_t_min_worst and its three shares
// VTI: the design grid (x = r1, y = r2 in m) with the shares ("share (1)", ...) and
// "k_t_min_worst (N/m)" as point arrays.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/five_bar_design_sweep.hpp"

namespace kinestat::io {

nlohmann::json design_sweep_to_json(const mechanisms::FiveBarDesignSweep& sweep);

// kInvalidInput naming the path when it cannot be written.
Status write_design_sweep_vti(const std::string& path, const mechanisms::FiveBarDesignSweep& sweep);

}  // namespace kinestat::io
