#include "io/vtk_files.hpp"

#include <fstream>

#include <fmt/format.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>

namespace kinestat::io {
namespace {

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

void add_units(vtkDataObject& data, const std::vector<std::pair<std::string, std::string>>& units) {
  vtkNew<vtkStringArray> a;
  a->SetName("units");
  for (const auto& [quantity, unit] : units) a->InsertNextValue(quantity + ": " + unit);
  data.GetFieldData()->AddArray(a);
}

void add_display_hints(vtkDataObject& data, const std::string& name, double model_size, double max_displacement) {
  if (!name.empty()) {
    vtkNew<vtkStringArray> a;
    a->SetName("load_case");
    a->InsertNextValue(name);
    data.GetFieldData()->AddArray(a);
  }
  if (max_displacement > 0.0 && model_size > 0.0) {
    vtkNew<vtkDoubleArray> w;
    w->SetName("warp_factor");
    w->InsertNextValue(0.1 * model_size / max_displacement);
    data.GetFieldData()->AddArray(w);
  }
}

Status write_pvd(const std::string& path, const std::vector<PvdEntry>& entries) {
  std::ofstream out(path);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (std::size_t i = 0; i < entries.size(); ++i)
    out << fmt::format("    <DataSet timestep=\"{}\" part=\"0\" name=\"{}\" file=\"{}\"/>\n", i,
                       xml_escape(entries[i].name), xml_escape(entries[i].file));
  out << "  </Collection>\n</VTKFile>\n";
  out.close();
  if (!out)
    return Status::Invalid(fmt::format("{}: cannot write the collection file; check the directory is writable", path));
  return Status::Ok();
}

}  // namespace kinestat::io
