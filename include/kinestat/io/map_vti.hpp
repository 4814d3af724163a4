// Workspace maps (mechanisms/workspace_map.hpp) for ParaView: VTK XML ImageData (.vti).
//
// The grid's origin, spacing and dimensions are the map's (m). Point data: one double array per field,
// named "FIELD (UNIT)" so that ParaView's colour legend states the unit ("k_t_min (N/m)"); NaN where
// a point has no value (never a filler number); "status" (unsigned char, MapPointStatus: 0 ok,
// 1 unreachable, 2 singular, 3 failed, 4 near-singular). With hide_masked_points, points without
// stiffness values (unreachable, singular, failed) are also marked HIDDENPOINT in "vtkGhostType", so
// ParaView leaves the cells that touch them blank. Field data: "length_unit" = "m", "status_values"
// (the codes in words), "description" (robot and mode) and, per field, "FIELD_unit".
#pragma once

#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::io {

struct MapVtiOptions {
  bool hide_masked_points = true;
};

// The VTI array name of a field: "k_t_min (N/m)".
std::string vti_array_name(mechanisms::MapField f);

// kInvalidInput naming the path when it cannot be written.
Status write_map_vti(const std::string& path, const mechanisms::WorkspaceMap& map, const MapVtiOptions& options = {});

}  // namespace kinestat::io
