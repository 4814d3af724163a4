#include "io/vtk_files.hpp"

#include <fmt/format.h>
#include <vtkDataObject.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkXMLWriter.h>

#include "kinestat/core/atomic_file.hpp"

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

Status write_vtk_xml(vtkXMLWriter& writer, const std::string& path) {
  return write_file_atomically(path, [&](const std::string& temp) {
    writer.SetFileName(temp.c_str());
    const int written = writer.Write();
    const unsigned long error = writer.GetErrorCode();
    writer.SetFileName(nullptr);
    // (vtkErrorCode's names would link VTK::CommonMisc for one message: the code is named here.)
    if (error == vtkErrorCode::OutOfDiskSpaceError)
      return Status::Invalid(fmt::format("{}: VTK could not write the file: out of disk space; free some", path));
    if (written != 1 || error != vtkErrorCode::NoError)
      return Status::Invalid(fmt::format("{}: VTK could not write the file (VTK error code {}); check that the "
                                         "folder is writable and has room",
                                         path, error));
    return Status::Ok();
  });
}

Status write_pvd(const std::string& path, const std::vector<PvdEntry>& entries) {
  std::string text = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (std::size_t i = 0; i < entries.size(); ++i)
    text += fmt::format("    <DataSet timestep=\"{}\" part=\"0\" name=\"{}\" file=\"{}\"/>\n", i,
                        xml_escape(entries[i].name), xml_escape(entries[i].file));
  text += "  </Collection>\n</VTKFile>\n";
  return write_text_file_atomically(path, text);
}

}  // namespace kinestat::io
