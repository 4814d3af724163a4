#include "io/vti_image.hpp"

#include <fmt/format.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataWriter.h>

#include "io/vtk_files.hpp"

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
  vtkNew<vtkXMLImageDataWriter> writer;
  writer->SetInputData(image);
  return write_vtk_xml(*writer, path);
}

}  // namespace kinestat::io
