// PNG pictures of workspace maps (mechanisms/workspace_map.hpp) and five-bar design sweeps
// (mechanisms/five_bar_design_sweep.hpp), as `kinestat map --png` and `kinestat design fivebar --png`
// draw them (io/map_png.hpp does the drawing). Axes in mm and values in the command line's mm-N-s
// display units: a person reads "N/mm", not "N/m".
#pragma once

#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/five_bar_design_sweep.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::io {

// How a map field is shown to people: its SI value times `scale` in `unit` (k_t_min in N/mm,
// rotational stiffness in N mm/deg, deflections in mm and deg; the others as in SI).
struct MapFieldDisplay {
  const char* unit;
  double scale;
};
MapFieldDisplay map_field_display(mechanisms::MapField f);

// One panel for a plane, a sheet of up to nine z slices for a box; the map's curves drawn over it;
// the condition number on a log scale. kInvalidInput naming the path when it cannot be written, or
// naming the field when the map does not have it.
Status write_workspace_map_png(const std::string& path, const mechanisms::WorkspaceMap& map,
                               mechanisms::MapField field);

// The picture's title: robot and mode, the field, and which part of the grid it shows ("slice
// z = 0 mm" for a plane of a box, "9 of the 41 slices z -100:100 mm" for a sheet).
std::string workspace_map_png_title(const mechanisms::WorkspaceMap& map, mechanisms::MapField field);

// "singularity measure >= 0.01, k_t_min >= 500 N/mm": the criteria of a sweep's share, in words.
std::string design_sweep_criteria(const mechanisms::FiveBarDesignSweep& sweep);

// The design map: the share (%) of the region over (r1, r2) in mm, the best design crossed, a title
// naming the region and the criteria. kInvalidInput naming the path when it cannot be written.
Status write_design_sweep_png(const std::string& path, const mechanisms::FiveBarDesignSweep& sweep);

}  // namespace kinestat::io
