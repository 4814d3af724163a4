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

// Field data "warp_factor": the Warp By Vector scale factor that draws the largest displacement
// `max_displacement` (m) as a tenth of the model's size `model_size` (m), so that 1e-9 m of a unit
// load is seen without guessing; absent when nothing moves. With "load_case" = `name` (may be empty).
void add_display_hints(vtkDataObject& data, const std::string& name, double model_size, double max_displacement);

// Runs `writer` (its input set) into memory, checks Write() and GetErrorCode(), and writes the
// text to `path` through write_text_file_atomically (core/atomic_file.hpp). kInvalidInput naming
// `path`.
Status write_vtk_xml(vtkXMLWriter& writer, const std::string& path);

// Makes the folder the VTK files go into (with its parents) if missing. kInvalidInput naming `dir`
// and the fix when it is an existing file or other non-folder ("give a directory") or cannot be made.
Status create_output_directory(const std::string& dir);

struct PvdEntry {
  std::string file;  // relative to the .pvd's folder
  std::string name;  // shown by ParaView
};

// ParaView's collection format: one DataSet per entry with timestep 0, 1, ..., so that the time
// slider steps through them. kInvalidInput naming the path when it cannot be written.
Status write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace kinestat::io
