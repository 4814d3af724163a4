#include "io/vti_image.hpp"

#include <fstream>

#include <fmt/format.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataWriter.h>

namespace kinestat::io {

vtkSmartPointer<vtkImageData> make_vti_image(const mechanisms::MapGrid& g) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(g.dimensions[0], g.dimensions[1], g.dimensions[2]);
  image->SetOrigin(g.origin.data());
  image->SetSpacing(g.spacing.data());
  return image;
}

namespace {
vtkSmartPointer<vtkDoubleArray> double_array(const std::string& name, const std::vector<double>& values) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (std::size_t i = 0; i < values.size(); ++i) a->SetValue(static_cast<vtkIdType>(i), values[i]);
  return a;
}
}  // namespace

void add_vti_point_array(vtkImageData* image, const std::string& name, const std::vector<double>& values) {
  image->GetPointData()->AddArray(double_array(name, values));
}

void add_vti_cell_array(vtkImageData* image, const std::string& name, const std::vector<double>& values) {
  image->GetCellData()->AddArray(double_array(name, values));
}

void add_vti_string(vtkImageData* image, const std::string& name, const std::string& value) {
  vtkNew<vtkStringArray> a;
  a->SetName(name.c_str());
  a->InsertNextValue(value);
  image->GetFieldData()->AddArray(a);
}

Status write_vti_image(const std::string& path, vtkImageData* image) {
  const auto refuse = [&] {
    return Status::Invalid(
        fmt::format("{}: cannot write the VTK file; check that the directory exists and is writable", path));
  };
  // Tried first: VTK's writer logs its own errors and still returns 1 for a file it cannot open.
  if (!std::ofstream(path)) return refuse();
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(image);
  if (writer->Write() != 1 || writer->GetErrorCode() != 0) return refuse();
  return Status::Ok();
}

}  // namespace kinestat::io
