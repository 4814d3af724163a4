// VTK ImageData on a regular grid (mechanisms::MapGrid), for the map and design-map writers.
#pragma once

#include <string>
#include <vector>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::io {

// Origin, spacing and dimensions of `grid` (m), no arrays yet.
vtkSmartPointer<vtkImageData> make_vti_image(const mechanisms::MapGrid& grid);
// A point array of doubles (NaN stays NaN: no value).
void add_vti_point_array(vtkImageData* image, const std::string& name, const std::vector<double>& values);
// A cell array of doubles, one value per cell (cells in x-fastest order).
void add_vti_cell_array(vtkImageData* image, const std::string& name, const std::vector<double>& values);
// A one-string field-data array (units, descriptions).
void add_vti_string(vtkImageData* image, const std::string& name, const std::string& value);
// Writes .vti; kInvalidInput naming the path when it cannot.
Status write_vti_image(const std::string& path, vtkImageData* image);

}  // namespace kinestat::io
