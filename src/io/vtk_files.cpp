#include "io/vtk_files.hpp"

#include <filesystem>
#include <system_error>

#include <fmt/format.h>
#include <vtkDataObject.h>
#include <vtkDoubleArray.h>
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
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
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

Status create_output_directory(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // A path naming a file (or /dev/null) is the usual mistake: said as such, not as "Not a directory".
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    return Status::Invalid(fmt::format(
        "{}: exists and is not a directory; the VTK files (one per load case or mode, and a .pvd) go into a "
        "directory: give a directory path (it is made if missing)",
        dir));
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    return Status::Invalid(fmt::format("{}: cannot create the output directory ({}); give a directory you can write to",
                                       dir, ec.message()));
  return Status::Ok();
}

Status write_vtk_xml(vtkXMLWriter& writer, const std::string& path) {
  // VTK writes into memory and the file is written by write_text_file_atomically: VTK 9.1's writers
  // crash on a full disk (vtkXMLUnstructuredDataWriter frees its position arrays twice) and log
  // their errors rather than return them for a file they cannot open.
  writer.WriteToOutputStringOn();
  const int written = writer.Write();
  const unsigned long error = writer.GetErrorCode();
  if (written != 1 || error != vtkErrorCode::NoError)
    return Status::Invalid(
        fmt::format("{}: VTK could not write the data (VTK error code {}); this is a bug, please "
                    "report it",
                    path, error));
  return write_text_file_atomically(path, writer.GetOutputString());
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
