// Workspace maps (mechanisms/workspace_map.hpp) for ParaView: VTK XML ImageData (.vti).
//
// The grid's origin, spacing and dimensions are the map's (m). Point data: one double array per field,
// named by the field alone ("k_t_min": no spaces or brackets, so ParaView's Calculator takes it
// unquoted), its unit in the field data "FIELD_unit"; NaN where a point has no value (never a filler
// number); "status" (unsigned char, PostureStatus: 0 ok, 1 unreachable, 2 singular, 3 failed,
// 4 near-singular); k_t_min is the active scalars. With hide_masked_points, points without stiffness
// values (unreachable, singular, failed) are marked HIDDENPOINT in the point "vtkGhostType" and the
// cells that touch them HIDDENCELL in the cell "vtkGhostType", so ParaView leaves them blank. Field
// data: "length_unit" = "m", "status_values" (the codes in words), "description" (robot and mode)
// and, per field, "FIELD_unit".
#pragma once

#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::io {

struct MapVtiOptions {
  bool hide_masked_points = true;
};

// The VTI array name of a field: its name, "k_t_min" (the unit is in "k_t_min_unit").
std::string vti_array_name(mechanisms::MapField f);

// kInvalidInput naming the path when it cannot be written.
Status write_map_vti(const std::string& path, const mechanisms::WorkspaceMap& map, const MapVtiOptions& options = {});

}  // namespace kinestat::io
