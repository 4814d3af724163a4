#include "kinestat/io/vtk_output.hpp"

#include "io/vtk_files.hpp"

#include <fmt/format.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;

vtkSmartPointer<vtkDoubleArray> double_array(const char* name, int components, vtkIdType tuples) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  a->Fill(0.0);
  return a;
}

vtkSmartPointer<vtkIntArray> int_array(const char* name, vtkIdType tuples) {
  auto a = vtkSmartPointer<vtkIntArray>::New();
  a->SetName(name);
  a->SetNumberOfTuples(tuples);
  return a;
}

// Point array from the first or last three components of per-node 6-vectors.
vtkSmartPointer<vtkDoubleArray> node_array(const char* name, const std::vector<Vec6>& v, bool rotation) {
  auto a = double_array(name, 3, static_cast<vtkIdType>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 x = rotation ? Vec3(v[i].tail<3>()) : Vec3(v[i].head<3>());
    a->SetTuple(static_cast<vtkIdType>(i), x.data());
  }
  return a;
}

// The undeformed model: points = nodes; cells = beams, then joints, then rigid links. A two-node
// element whose nodes coincide (every joint, a zero-offset link) is a 2-point VTK_POLY_VERTEX, which
// ParaView draws as points; a zero-length VTK_LINE would be invisible.
vtkSmartPointer<vtkUnstructuredGrid> geometry(const msa::Structure& s) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (const auto& n : s.nodes()) points->InsertNextPoint(n.position.data());
  grid->SetPoints(points);

  const vtkIdType cells = static_cast<vtkIdType>(s.beams().size() + s.joints().size() + s.rigid_links().size());
  grid->Allocate(cells);
  auto type = int_array("element_type", cells);
  auto id = int_array("element_id", cells);
  const double tol = 1e-9 * s.length_scale();
  auto add = [&](int n1, int n2, int element_type, std::size_t index) {
    const vtkIdType ids[2] = {n1, n2};
    const bool coincident = (s.nodes()[n1].position - s.nodes()[n2].position).norm() <= tol;
    const vtkIdType c = grid->InsertNextCell(coincident ? VTK_POLY_VERTEX : VTK_LINE, 2, ids);
    type->SetValue(c, element_type);
    id->SetValue(c, static_cast<int>(index));
  };
  for (std::size_t i = 0; i < s.beams().size(); ++i) add(s.beams()[i].node1, s.beams()[i].node2, kVtkBeam, i);
  for (std::size_t i = 0; i < s.joints().size(); ++i) add(s.joints()[i].node1, s.joints()[i].node2, kVtkJoint, i);
  for (std::size_t i = 0; i < s.rigid_links().size(); ++i) {
    add(s.rigid_links()[i].master, s.rigid_links()[i].slave, kVtkRigidLink, i);
  }
  grid->GetCellData()->AddArray(type);
  grid->GetCellData()->AddArray(id);
  add_units(*grid, {{"coordinates", "m"},
                    {"displacement", "m"},
                    {"rotation", "rad"},
                    {"reaction_force", "N"},
                    {"reaction_moment", "N m"},
                    {"end_forces", "N (N Vy Vz), N m (T My Mz)"},
                    {"axial_force", "N"},
                    {"torsion", "N m"},
                    {"bending_moment_y", "N m"},
                    {"bending_moment_z", "N m"},
                    {"joint_force", "N (force), N m (moment)"},
                    {"free_motion_K", "- (a shape: only ratios count)"}});
  return grid;
}

// Load-case results as point and cell arrays. Cell order matches geometry().
void add_load_case(const msa::Structure& s, const msa::LoadCaseResult& r, vtkUnstructuredGrid* grid) {
  vtkPointData* pd = grid->GetPointData();
  pd->AddArray(node_array("displacement", r.displacement, false));
  pd->AddArray(node_array("rotation", r.displacement, true));
  pd->AddArray(node_array("reaction_force", r.reaction, false));
  pd->AddArray(node_array("reaction_moment", r.reaction, true));
  pd->SetActiveVectors("displacement");  // Warp By Vector picks it up directly
  add_display_hints(*grid, r.name, s.length_scale(), r.max_translation);

  const vtkIdType cells = grid->GetNumberOfCells();
  auto end_forces = double_array("end_forces", 12, cells);
  auto axial = double_array("axial_force", 1, cells);
  auto torsion = double_array("torsion", 1, cells);
  auto my = double_array("bending_moment_y", 1, cells);
  auto mz = double_array("bending_moment_z", 1, cells);
  auto joint = double_array("joint_force", 6, cells);
  for (std::size_t i = 0; i < r.beam_end_forces.size(); ++i) {
    const Vec12& f = r.beam_end_forces[i];
    const auto c = static_cast<vtkIdType>(i);
    end_forces->SetTuple(c, f.data());
    // End forces act on the beam: the force at end 2 along local x is the tension.
    axial->SetValue(c, f(6));
    torsion->SetValue(c, f(9));
    my->SetValue(c, std::max(std::abs(f(4)), std::abs(f(10))));
    mz->SetValue(c, std::max(std::abs(f(5)), std::abs(f(11))));
  }
  for (std::size_t i = 0; i < r.joint_forces.size(); ++i) {
    joint->SetTuple(static_cast<vtkIdType>(s.beams().size() + i), r.joint_forces[i].data());
  }
  for (const auto& a : {end_forces, axial, torsion, my, mz, joint}) grid->GetCellData()->AddArray(a);
}

void add_free_motions(const msa::SingularityDiagnosis& d, vtkUnstructuredGrid* grid) {
  for (std::size_t k = 0; k < d.modes.size(); ++k) {
    const std::string name = fmt::format("free_motion_{}", k + 1);
    grid->GetPointData()->AddArray(node_array(name.c_str(), d.modes[k].node_motion, false));
    grid->GetPointData()->AddArray(node_array((name + "_rotation").c_str(), d.modes[k].node_motion, true));
  }
  if (!d.modes.empty() && !grid->GetPointData()->GetVectors()) grid->GetPointData()->SetActiveVectors("free_motion_1");
}

Status write_grid(vtkUnstructuredGrid* grid, const std::string& path) {
  auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
  writer->SetInputData(grid);
  return write_vtk_xml(*writer, path);
}

// The output folder, made if missing, and the files written into it, collected for the .pvd.
class Collection {
 public:
  Collection(std::string dir, std::vector<std::string>* written) : dir_(std::move(dir)), written_(written) {}
  Status create() const { return create_output_directory(dir_); }
  Status emit(vtkUnstructuredGrid* grid, std::string file, std::string name) {
    const std::string path = (fs::path(dir_) / file).string();
    if (Status st = write_grid(grid, path); !st.ok()) return st;
    if (written_) written_->push_back(path);
    entries_.push_back({std::move(file), std::move(name)});
    return Status::Ok();
  }
  Status finish(const std::string& basename) {
    const std::string pvd = (fs::path(dir_) / (basename + ".pvd")).string();
    if (Status st = write_pvd(pvd, entries_); !st.ok()) return st;
    if (written_) written_->push_back(pvd);
    return Status::Ok();
  }

 private:
  std::string dir_;
  std::vector<std::string>* written_;
  std::vector<PvdEntry> entries_;
};

}  // namespace

Status write_vtk(const msa::Structure& s, const msa::Solution& sol, const std::string& dir, const std::string& basename,
                 std::vector<std::string>* written) {
  if (Status st = msa::check_solution_matches(s, sol); !st.ok()) return st;
  Collection files(dir, written);
  if (Status st = files.create(); !st.ok()) return st;
  auto emit = [&](vtkUnstructuredGrid* grid, std::string file, std::string name) {
    return files.emit(grid, std::move(file), std::move(name));
  };
  for (std::size_t i = 0; i < sol.cases.size(); ++i) {
    auto grid = geometry(s);
    add_load_case(s, sol.cases[i], grid);
    add_free_motions(sol.singularity, grid);
    if (Status st = emit(grid, fmt::format("{}_case{}.vtu", basename, i + 1), sol.cases[i].name); !st.ok()) return st;
  }
  if (sol.cases.empty()) {
    auto grid = geometry(s);
    add_free_motions(sol.singularity, grid);
    if (Status st = emit(grid, basename + "_undeformed.vtu", "undeformed"); !st.ok()) return st;
  }

  return files.finish(basename);
}

Status write_beam_diagrams_vtk(const msa::Structure& s, const msa::Solution& sol,
                               const std::vector<std::vector<msa::BeamStations>>& stations, const std::string& dir,
                               const std::string& basename, std::vector<std::string>* written) {
  if (Status st = msa::check_solution_matches(s, sol); !st.ok()) return st;
  if (stations.size() != sol.cases.size())
    return Status::Internal(
        fmt::format("beam diagrams: stations of {} load cases for {}", stations.size(), sol.cases.size()));
  Collection files(dir, written);
  if (Status st = files.create(); !st.ok()) return st;
  static constexpr const char* kForces[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
  for (std::size_t c = 0; c < sol.cases.size(); ++c) {
    if (stations[c].size() != s.beams().size())
      return Status::Internal(
          fmt::format("beam diagrams: stations of {} beams for {}", stations[c].size(), s.beams().size()));
    vtkIdType count = 0;
    for (const msa::BeamStations& b : stations[c]) count += static_cast<vtkIdType>(b.x.size());
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    std::vector<vtkSmartPointer<vtkDoubleArray>> forces;
    for (const char* name : kForces) forces.push_back(double_array(name, 1, count));
    auto displacement = double_array("displacement", 3, count);
    auto mz = double_array("Mz_diagram", 3, count), my = double_array("My_diagram", 3, count);
    auto beam_id = int_array("element_id", static_cast<vtkIdType>(s.beams().size()));
    double max_moment = 0.0;
    vtkIdType k = 0;
    for (std::size_t b = 0; b < s.beams().size(); ++b) {
      const msa::Beam& beam = s.beams()[b];
      const Mat3 axes = s.beam_axes(beam);  // columns: local x, y, z in global
      const Vec3& p1 = s.nodes()[beam.node1].position;
      const msa::BeamStations& st = stations[c][b];
      std::vector<vtkIdType> ids;
      for (std::size_t i = 0; i < st.x.size(); ++i, ++k) {
        const Vec3 p = p1 + st.x[i] * axes.col(0);
        points->InsertNextPoint(p.data());
        for (int f = 0; f < 6; ++f) forces[f]->SetValue(k, st.forces[i](f));
        const Vec3 u = axes * st.displacement[i].head<3>();
        const Vec3 vy = st.forces[i](5) * axes.col(1), vz = st.forces[i](4) * axes.col(2);
        displacement->SetTuple(k, u.data());
        mz->SetTuple(k, vy.data());
        my->SetTuple(k, vz.data());
        max_moment = std::max({max_moment, std::abs(st.forces[i](4)), std::abs(st.forces[i](5))});
        ids.push_back(k);
      }
      grid->InsertNextCell(VTK_POLY_LINE, static_cast<vtkIdType>(ids.size()), ids.data());
      beam_id->SetValue(static_cast<vtkIdType>(b), static_cast<int>(b));
    }
    grid->SetPoints(points);
    for (auto& f : forces) grid->GetPointData()->AddArray(f);
    grid->GetPointData()->AddArray(displacement);
    grid->GetPointData()->AddArray(mz);
    grid->GetPointData()->AddArray(my);
    grid->GetPointData()->SetActiveVectors("Mz_diagram");
    grid->GetCellData()->AddArray(beam_id);
    add_units(*grid, {{"coordinates", "m"},
                      {"N", "N"},
                      {"Vy", "N"},
                      {"Vz", "N"},
                      {"T", "N m"},
                      {"My", "N m"},
                      {"Mz", "N m"},
                      {"displacement", "m"},
                      {"Mz_diagram", "N m (along local y)"},
                      {"My_diagram", "N m (along local z)"}});
    add_display_hints(*grid, sol.cases[c].name, s.length_scale(), max_moment);
    if (Status st = files.emit(grid, fmt::format("{}_diagram_case{}.vtu", basename, c + 1), sol.cases[c].name);
        !st.ok())
      return st;
  }
  return files.finish(basename + "_diagram");
}

Status write_mode_shapes_vtk(const msa::Structure& s, const std::vector<VtkModeShape>& modes, const std::string& dir,
                             const std::string& basename, const std::string& shape_unit,
                             std::vector<std::string>* written) {
  for (const VtkModeShape& m : modes)
    if (m.shape.size() != s.nodes().size())
      return Status::Invalid(fmt::format("mode '{}': {} node motions for a structure of {} nodes", m.name,
                                         m.shape.size(), s.nodes().size()));
  Collection files(dir, written);
  if (Status st = files.create(); !st.ok()) return st;
  for (std::size_t k = 0; k < modes.size(); ++k) {
    auto grid = geometry(s);
    // Replaces the geometry's list (this file has no load-case arrays).
    add_units(*grid, {{"coordinates", "m"}, {"mode_shape", shape_unit}, {"mode_rotation", shape_unit}});
    grid->GetPointData()->AddArray(node_array("mode_shape", modes[k].shape, false));
    grid->GetPointData()->AddArray(node_array("mode_rotation", modes[k].shape, true));
    grid->GetPointData()->SetActiveVectors("mode_shape");
    double max_translation = 0.0;
    for (const Vec6& v : modes[k].shape) max_translation = std::max(max_translation, v.head<3>().norm());
    add_display_hints(*grid, modes[k].name, s.length_scale(), max_translation);
    if (Status st = files.emit(grid, fmt::format("{}_mode{}.vtu", basename, k + 1), modes[k].name); !st.ok()) return st;
  }
  return files.finish(basename);
}

}  // namespace kinestat::io
