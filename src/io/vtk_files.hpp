// What every VTK file of kinestat carries (its units) and the .pvd collection that groups files.
// Internal to io.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "kinestat/core/status.hpp"

class vtkDataObject;
class vtkXMLWriter;

namespace kinestat::io {

// Field data "units": one string "QUANTITY: UNIT" per entry, e.g. {"coordinates", "m"}, so the
// units travel with the file (ParaView lists field data in its Information panel).
void add_units(vtkDataObject& data, const std::vector<std::pair<std::string, std::string>>& units);

// Runs `writer` (its input set) into memory, checks Write() and GetErrorCode(), and writes the
// text to `path` through write_text_file_atomically (core/atomic_file.hpp). kInvalidInput naming
// `path`.
Status write_vtk_xml(vtkXMLWriter& writer, const std::string& path);

struct PvdEntry {
  std::string file;  // relative to the .pvd's folder
  std::string name;  // shown by ParaView
};

// ParaView's collection format: one DataSet per entry with timestep 0, 1, ..., so that the time
// slider steps through them. kInvalidInput naming the path when it cannot be written.
Status write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace kinestat::io
