#include "kinestat/io/map_vti.hpp"

#include <fmt/format.h>
#include <vtkDataSetAttributes.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>

namespace kinestat::io {
namespace {

using mechanisms::MapPointStatus;

void add_string(vtkFieldData* data, const std::string& name, const std::string& value) {
  vtkNew<vtkStringArray> a;
  a->SetName(name.c_str());
  a->InsertNextValue(value);
  data->AddArray(a);
}

}  // namespace

std::string vti_array_name(mechanisms::MapField f) {
  const mechanisms::MapFieldInfo& info = mechanisms::field_info(f);
  return fmt::format("{} ({})", info.name, info.unit);
}

Status write_map_vti(const std::string& path, const mechanisms::WorkspaceMap& map, const MapVtiOptions& options) {
  const mechanisms::MapGrid& g = map.grid;
  const auto n = static_cast<vtkIdType>(g.num_points());
  vtkNew<vtkImageData> image;
  image->SetDimensions(g.dimensions[0], g.dimensions[1], g.dimensions[2]);
  image->SetOrigin(g.origin.data());
  image->SetSpacing(g.spacing.data());

  for (const mechanisms::FieldValues& f : map.fields) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(vti_array_name(f.field).c_str());
    a->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i) a->SetValue(i, f.values[i]);
    image->GetPointData()->AddArray(a);
  }
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

  vtkFieldData* fd = image->GetFieldData();
  add_string(fd, "length_unit", "m");
  add_string(fd, "description", map.description);
  std::string codes;
  for (int s = 0; s < mechanisms::kNumMapPointStatuses; ++s)
    codes += fmt::format("{}{} {}", s ? ", " : "", s, to_string(static_cast<MapPointStatus>(s)));
  add_string(fd, "status_values", codes);
  for (const mechanisms::FieldValues& f : map.fields) {
    const mechanisms::MapFieldInfo& info = mechanisms::field_info(f.field);
    add_string(fd, fmt::format("{}_unit", info.name), info.unit);
  }

  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  if (writer->Write() != 1)
    return Status::Invalid(fmt::format("{}: cannot write the VTK file; check that the directory exists and is writable",
                                       path));
  return Status::Ok();
}

}  // namespace kinestat::io
