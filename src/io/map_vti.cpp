#include "kinestat/io/map_vti.hpp"

#include <fmt/format.h>
#include <vtkCellData.h>
#include <vtkDataSetAttributes.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include "io/vti_image.hpp"

namespace kinestat::io {

using mechanisms::PostureStatus;

std::string vti_array_name(mechanisms::MapField f) { return mechanisms::field_info(f).name; }

Status write_map_vti(const std::string& path, const mechanisms::WorkspaceMap& map, const MapVtiOptions& options) {
  const auto n = static_cast<vtkIdType>(map.grid.num_points());
  vtkSmartPointer<vtkImageData> image = make_vti_image(map.grid);
  for (const mechanisms::FieldValues& f : map.fields) add_vti_point_array(image, vti_array_name(f.field), f.values);
  vtkNew<vtkUnsignedCharArray> status;
  status->SetName("status");
  status->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i) status->SetValue(i, static_cast<unsigned char>(map.status[i]));
  image->GetPointData()->AddArray(status);
  if (options.hide_masked_points) {
    vtkNew<vtkUnsignedCharArray> ghost;
    ghost->SetName(vtkDataSetAttributes::GhostArrayName());
    ghost->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      ghost->SetValue(i, mechanisms::has_values(map.status[i]) ? 0 : vtkDataSetAttributes::HIDDENPOINT);
    image->GetPointData()->AddArray(ghost);
    // Cells that touch a hidden point, hidden too: the Surface representation and every filter
    // (Slice, Contour, Threshold) then leave them out instead of painting them in the NaN colour.
    vtkNew<vtkUnsignedCharArray> hidden_cells;
    hidden_cells->SetName(vtkDataSetAttributes::GhostArrayName());
    hidden_cells->SetNumberOfTuples(image->GetNumberOfCells());
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < image->GetNumberOfCells(); ++c) {
      image->GetCellPoints(c, ids);
      bool hide = false;
      for (vtkIdType k = 0; k < ids->GetNumberOfIds() && !hide; ++k)
        hide = !mechanisms::has_values(map.status[static_cast<std::size_t>(ids->GetId(k))]);
      hidden_cells->SetValue(c, hide ? vtkDataSetAttributes::HIDDENCELL : 0);
    }
    image->GetCellData()->AddArray(hidden_cells);
  }
  // ParaView colours by the active scalars on opening: the weakest-direction stiffness, the map's
  // headline field, rather than the first array in the file.
  for (const mechanisms::FieldValues& f : map.fields)
    if (f.field == mechanisms::MapField::kTranslationalMin)
      image->GetPointData()->SetActiveScalars(vti_array_name(f.field).c_str());

  add_vti_string(image, "length_unit", "m");
  const mechanisms::MapGrid& grid = map.grid;
  add_vti_string(image, "axis_names", fmt::format("{},{},{}", grid.names[0], grid.names[1], grid.names[2]));
  add_vti_string(image, "axis_units",
                 fmt::format("{},{},{}", mechanisms::axis_unit(grid, 0), mechanisms::axis_unit(grid, 1),
                             mechanisms::axis_unit(grid, 2)));
  add_vti_string(image, "description", map.description);
  std::string codes;
  for (int s = 0; s < mechanisms::kNumPostureStatuses; ++s)
    codes += fmt::format("{}{} {}", s ? ", " : "", s, to_string(static_cast<PostureStatus>(s)));
  add_vti_string(image, "status_values", codes);
  for (const mechanisms::FieldValues& f : map.fields) {
    const mechanisms::MapFieldInfo& info = mechanisms::field_info(f.field);
    add_vti_string(image, fmt::format("{}_unit", info.name), info.unit);
  }
  return write_vti_image(path, image);
}

}  // namespace kinestat::io
