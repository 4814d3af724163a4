#include "kinestat/io/workspace_vtk.hpp"

#include "io/vtk_files.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "kinestat/core/input_checks.hpp"

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;
using mechanisms::VelocityTransmission;

// A grid of points (m) with the transmission point data, filled point by point.
class WorkspaceGrid {
 public:
  WorkspaceGrid() {
    grid_->SetPoints(points_);
    points_->SetDataTypeToDouble();
    for (auto* a : {mu_min_.Get(), mu_max_.Get(), condition_.Get(), manipulability_.Get(), rho_.Get()})
      grid_->GetPointData()->AddArray(a);
    mu_min_->SetName("mu_min");
    mu_max_->SetName("mu_max");
    condition_->SetName("condition_number");
    manipulability_->SetName("manipulability");
    rho_->SetName("rho");
    rho_->SetNumberOfComponents(3);
    add_units(*grid_, {{"coordinates", "m"},
                       {"rho", "m"},
                       {"mu_min", "-"},
                       {"mu_max", "-"},
                       {"condition_number", "-"},
                       {"manipulability", "-"}});
  }

  vtkIdType add_point(const Vec3& p, const Vec3& rho, const VelocityTransmission& v) {
    mu_min_->InsertNextValue(v.mu_min);
    mu_max_->InsertNextValue(v.mu_max);
    condition_->InsertNextValue(v.condition_number);
    manipulability_->InsertNextValue(v.manipulability);
    rho_->InsertNextTuple(rho.data());
    return points_->InsertNextPoint(p.data());
  }

  // Corners in VTK_HEXAHEDRON order: the bottom face (x, then y) counter-clockwise, then the top.
  void add_hexahedron(const std::array<vtkIdType, 8>& corners) {
    grid_->InsertNextCell(VTK_HEXAHEDRON, 8, corners.data());
  }

  Status write(const std::string& path) {
    auto writer = vtkSmartPointer<vtkXMLUnstructuredGridWriter>::New();
    writer->SetInputData(grid_);
    return write_vtk_xml(*writer, path);
  }

 private:
  vtkSmartPointer<vtkUnstructuredGrid> grid_ = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkSmartPointer<vtkPoints> points_ = vtkSmartPointer<vtkPoints>::New();
  vtkSmartPointer<vtkDoubleArray> mu_min_ = vtkSmartPointer<vtkDoubleArray>::New();
  vtkSmartPointer<vtkDoubleArray> mu_max_ = vtkSmartPointer<vtkDoubleArray>::New();
  vtkSmartPointer<vtkDoubleArray> condition_ = vtkSmartPointer<vtkDoubleArray>::New();
  vtkSmartPointer<vtkDoubleArray> manipulability_ = vtkSmartPointer<vtkDoubleArray>::New();
  vtkSmartPointer<vtkDoubleArray> rho_ = vtkSmartPointer<vtkDoubleArray>::New();
};

// Offsets of the hexahedron corners in the (i, j, k) grid, VTK order.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

Status write_joint_workspace(const mechanisms::OrthoglideDesign& d, int n, const std::string& path) {
  const mechanisms::JointWorkspaceSamples s = mechanisms::sample_joint_workspace(d, n);
  WorkspaceGrid grid;
  std::vector<vtkIdType> id(s.valid.size(), -1);
  for (std::size_t i = 0; i < s.valid.size(); ++i)
    if (s.valid[i]) id[i] = grid.add_point(s.p[i], s.rho[i], s.factors[i]);
  auto index = [n](int i, int j, int k) {
    return i + static_cast<std::size_t>(n) * (j + static_cast<std::size_t>(n) * k);
  };
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) {
        std::array<vtkIdType, 8> corners;
        bool complete = true;
        for (int c = 0; c < 8; ++c) {
          corners[c] = id[index(i + kCorner[c][0], j + kCorner[c][1], k + kCorner[c][2])];
          complete = complete && corners[c] >= 0;
        }
        if (complete) grid.add_hexahedron(corners);
      }
  return grid.write(path);
}

Status write_cube(const mechanisms::OrthoglideDesign& d, const std::string& path) {
  const mechanisms::OrthoglideGeometry g{d.link_length};
  WorkspaceGrid grid;
  std::array<vtkIdType, 8> corners;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p(kCorner[c][0] ? d.p_max : d.p_min, kCorner[c][1] ? d.p_max : d.p_min,
                 kCorner[c][2] ? d.p_max : d.p_min);
    auto rho = mechanisms::inverse_kinematics(g, p);
    if (!rho.ok()) return rho.status();
    auto v = mechanisms::velocity_transmission_at(g, p);
    if (!v.ok()) return v.status();
    corners[c] = grid.add_point(p, *rho, *v);
  }
  grid.add_hexahedron(corners);
  return grid.write(path);
}

}  // namespace

Status write_orthoglide_workspace_vtk(const mechanisms::OrthoglideDesign& d, int n, const std::string& dir,
                                      std::vector<std::string>* written, double max_points) {
  if (n < 2) return Status::Invalid(fmt::format("VTK workspace grid of {} points per joint: need at least 2", n));
  if (Status st = check_size(std::pow(n, 3.0), max_points, fmt::format("VTK workspace grid of {} points per joint", n),
                             "points (n^3)", "give fewer points per joint or raise the point limit");
      !st.ok())
    return st;
  if (Status st = create_output_directory(dir); !st.ok()) return st;
  const std::string stem = (fs::path(dir) / fmt::format("orthoglide_s{}_", d.strategy)).string();
  const std::string joint_path = stem + "joint_workspace.vtu", cube_path = stem + "cube.vtu";
  if (Status st = write_joint_workspace(d, n, joint_path); !st.ok()) return st;
  if (written) written->push_back(joint_path);
  if (Status st = write_cube(d, cube_path); !st.ok()) return st;
  if (written) written->push_back(cube_path);
  return Status::Ok();
}

}  // namespace kinestat::io
