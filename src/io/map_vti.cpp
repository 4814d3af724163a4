#include "kinestat/io/map_vti.hpp"

#include <fmt/format.h>
#include <vtkDataSetAttributes.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include "io/vti_image.hpp"

namespace kinestat::io {

using mechanisms::MapPointStatus;

std::string vti_array_name(mechanisms::MapField f) {
  const mechanisms::MapFieldInfo& info = mechanisms::field_info(f);
  return fmt::format("{} ({})", info.name, info.unit);
}

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
  }

  add_vti_string(image, "length_unit", "m");
  add_vti_string(image, "description", map.description);
  std::string codes;
  for (int s = 0; s < mechanisms::kNumMapPointStatuses; ++s)
    codes += fmt::format("{}{} {}", s ? ", " : "", s, to_string(static_cast<MapPointStatus>(s)));
  add_vti_string(image, "status_values", codes);
  for (const mechanisms::FieldValues& f : map.fields) {
    const mechanisms::MapFieldInfo& info = mechanisms::field_info(f.field);
    add_vti_string(image, fmt::format("{}_unit", info.name), info.unit);
  }
  return write_vti_image(path, image);
}

}  // namespace kinestat::io
