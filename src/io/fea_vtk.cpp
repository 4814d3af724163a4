#include "kinestat/io/fea_vtk.hpp"

#include "io/vtk_files.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

namespace kinestat::io {

const char* link_load_case_name(int k) {
  static const char* kNames[6] = {"Fx", "Fy", "Fz", "Mx", "My", "Mz"};
  return kNames[k];
}

namespace {

// The mesh as an unstructured grid (coordinates in m).
vtkNew<vtkUnstructuredGrid> link_grid(const fea::TetMesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i) points->SetPoint(i, mesh.nodes[i].data());
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->Allocate(mesh.num_elements());
  // Our 10-node order is VTK_QUADRATIC_TETRA's (fea/tet_mesh.hpp).
  const int type = mesh.quadratic() ? VTK_QUADRATIC_TETRA : VTK_TETRA;
  std::vector<vtkIdType> ids(mesh.nodes_per_element);
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int* v = mesh.element(e);
    for (int a = 0; a < mesh.nodes_per_element; ++a) ids[a] = v[a];
    grid->InsertNextCell(type, mesh.nodes_per_element, ids.data());
  }
  return grid;
}

// The point vector `name` (one Vec3 per node), made the active vectors, and the display hints for it
// (ParaView's Warp By Vector scale); `label` is the load case or mode.
void add_node_vectors(vtkUnstructuredGrid& grid, const std::string& name, const std::vector<Vec3>& values,
                      const std::string& label) {
  vtkNew<vtkDoubleArray> u;
  u->SetName(name.c_str());
  u->SetNumberOfComponents(3);
  u->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  double largest = 0.0;
  for (size_t i = 0; i < values.size(); ++i) {
    u->SetTuple(static_cast<vtkIdType>(i), values[i].data());
    largest = std::max(largest, values[i].norm());
  }
  grid.GetPointData()->AddArray(u);
  grid.GetPointData()->SetActiveVectors(name.c_str());
  double size = 0.0;
  if (grid.GetNumberOfPoints() > 0) {
    double b[6];
    grid.GetBounds(b);
    size = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
  }
  add_display_hints(grid, label, size, largest);
}

}  // namespace

Status write_link_vtu(const std::string& path, const fea::TetMesh& mesh, const fea::LinkStiffness& result, int k) {
  if (k < 0 || k > 5 || result.displacement[k].size() != static_cast<size_t>(mesh.num_nodes()) ||
      result.von_mises[k].size() != static_cast<size_t>(mesh.num_elements()))
    return Status::Invalid(
        fmt::format("{}: no displacement field of load case {} for this mesh (compute the link "
                    "stiffness with keep_fields on the same mesh)",
                    path, k));
  auto grid = link_grid(mesh);
  const bool force = k < 3;
  add_node_vectors(*grid, "displacement", result.displacement[k], "");
  vtkNew<vtkDoubleArray> vm;
  vm->SetName("von_mises");
  vm->SetNumberOfTuples(mesh.num_elements());
  for (int e = 0; e < mesh.num_elements(); ++e) vm->SetValue(e, result.von_mises[k][e]);
  grid->GetCellData()->AddArray(vm);
  // Units and load case travel with the file (ParaView shows field data in its information panel).
  vtkNew<vtkStringArray> note;
  note->SetName("load_case");
  note->InsertNextValue(
      fmt::format("unit {} = 1 {} on the reference point ({:g}, {:g}, {:g}) m; coordinates m, "
                  "displacement m per {}, von_mises Pa per {}",
                  link_load_case_name(k), force ? "N" : "N m", result.cartesian.point.x(), result.cartesian.point.y(),
                  result.cartesian.point.z(), force ? "N" : "N m", force ? "N" : "N m"));
  grid->GetFieldData()->AddArray(note);
  const std::string per = force ? "N" : "N m";
  add_units(*grid, {{"coordinates", "m"}, {"displacement", "m per " + per}, {"von_mises", "Pa per " + per}});
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetDataModeToBinary();
  return write_vtk_xml(*writer, path);
}

Status write_link_vtu_files(const std::string& dir, const std::string& prefix, const fea::TetMesh& mesh,
                            const fea::LinkStiffness& result, std::vector<std::string>* written) {
  if (Status st = create_output_directory(dir); !st.ok()) return st;
  std::vector<PvdEntry> entries;
  for (int k = 0; k < 6; ++k) {
    const std::string file = prefix + "_" + link_load_case_name(k) + ".vtu";
    const std::string path = (std::filesystem::path(dir) / file).string();
    if (Status s = write_link_vtu(path, mesh, result, k); !s.ok()) return s;
    if (written) written->push_back(path);
    entries.push_back({file, link_load_case_name(k)});
  }
  const std::string pvd = (std::filesystem::path(dir) / (prefix + ".pvd")).string();
  if (Status s = write_pvd(pvd, entries); !s.ok()) return s;
  if (written) written->push_back(pvd);
  return Status::Ok();
}

std::string link_mode_name(const fea::LinkMode& m, int k) {
  return fmt::format("mode {}: {:.6g} Hz", k + 1, m.frequency);
}

Status write_link_mode_vtu(const std::string& path, const fea::TetMesh& mesh, const fea::LinkStiffness& result, int k) {
  if (k < 0 || k >= static_cast<int>(result.modes.size()) ||
      result.modes[k].shape.size() != static_cast<size_t>(mesh.num_nodes()))
    return Status::Invalid(
        fmt::format("{}: no shape of mode {} for this mesh (compute the link modes with keep_fields "
                    "on the same mesh)",
                    path, k + 1));
  const fea::LinkMode& m = result.modes[k];
  auto grid = link_grid(mesh);
  add_node_vectors(*grid, "mode_shape", m.shape, link_mode_name(m, k));
  vtkNew<vtkStringArray> note;
  note->SetName("mode");
  note->InsertNextValue(
      fmt::format("mode {} of the link clamped at its origin, reference body massless: {:.9g} Hz "
                  "({:.9g} rad/s); mode_shape mass-normalized (q' M q = 1), m/sqrt(kg)",
                  k + 1, m.frequency, m.omega));
  grid->GetFieldData()->AddArray(note);
  vtkNew<vtkDoubleArray> frequency;
  frequency->SetName("frequency_Hz");
  frequency->InsertNextValue(m.frequency);
  grid->GetFieldData()->AddArray(frequency);
  add_units(*grid, {{"coordinates", "m"}, {"mode_shape", "m/sqrt(kg)"}, {"frequency_Hz", "Hz"}});
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetInputData(grid);
  writer->SetDataModeToBinary();
  return write_vtk_xml(*writer, path);
}

Status write_link_mode_vtu_files(const std::string& dir, const std::string& prefix, const fea::TetMesh& mesh,
                                 const fea::LinkStiffness& result, std::vector<std::string>* written) {
  if (Status st = create_output_directory(dir); !st.ok()) return st;
  std::vector<PvdEntry> entries;
  for (int k = 0; k < static_cast<int>(result.modes.size()); ++k) {
    const std::string file = fmt::format("{}_modes_mode{}.vtu", prefix, k + 1);
    const std::string path = (std::filesystem::path(dir) / file).string();
    if (Status s = write_link_mode_vtu(path, mesh, result, k); !s.ok()) return s;
    if (written) written->push_back(path);
    entries.push_back({file, link_mode_name(result.modes[k], k)});
  }
  const std::string pvd = (std::filesystem::path(dir) / (prefix + "_modes.pvd")).string();
  if (Status s = write_pvd(pvd, entries); !s.ok()) return s;
  if (written) written->push_back(pvd);
  return Status::Ok();
}

}  // namespace kinestat::io
