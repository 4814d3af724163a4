// Workspace maps (mechanisms/workspace_map.hpp) as JSON, schema "kinestat-workspace-map" (docs/maps.md):
//   grid:    origin, spacing (m), dimensions, units, order (x fastest)
//   fields:  {name: flat array over the grid points, x fastest, null where the point has no value}
//   units:   {name: SI unit}
//   status:  flat array of PostureStatus codes; status_codes: {code: word}
//   summary: per field count, min, max, mean, argmin (m); status counts; reachable and stiff area
//            (m^2) or volume (m^3)
//   curves:  {label: [polyline [[x, y, z], ...] (m), ...]}
#pragma once

#include <nlohmann/json.hpp>

#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::io {

inline constexpr int kMapSchemaVersion = 1;

nlohmann::json workspace_map_to_json(const mechanisms::WorkspaceMap& map);

// The "grid" object: origin, spacing (m), dimensions, num_points, units, order.
nlohmann::json map_grid_to_json(const mechanisms::MapGrid& grid);

}  // namespace kinestat::io
