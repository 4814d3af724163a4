// The deformed-link .vtu files read back with VTK's own reader.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/tet_mesh.hpp"
#include "kinestat/io/fea_vtk.hpp"

namespace kinestat::io {
namespace {

TEST(FeaVtk, SixFilesReadBackWithFieldsAndUniformAxialStress) {
  constexpr double L = 0.2, b = 0.02, h = 0.03;
  const fea::TetMesh linear = fea::make_box_mesh(Vec3(0, -b / 2, -h / 2), Vec3(L, b / 2, h / 2), 20, 2, 3);
  const fea::TetMesh mesh = fea::to_quadratic(linear);
  const int corner = linear.num_nodes() - 1;  // the box's corner (L, b/2, h/2): vertices keep their numbers
  fea::LinkStiffnessOptions o;
  o.clamp = fea::Region::plane(Vec3::Zero(), Vec3::UnitX());
  o.reference = fea::Region::plane(Vec3(L, 0, 0), Vec3::UnitX());
  o.keep_fields = true;
  auto r = fea::link_stiffness(mesh, Material::from_E_nu("steel", 210e9, 0.3), o);
  ASSERT_TRUE(r.ok()) << r.status().message();
  const std::string dir = (std::filesystem::temp_directory_path() / "kinestat_fea_vtk_test").string();
  std::filesystem::remove_all(dir);
  std::vector<std::string> written;
  ASSERT_TRUE(write_link_vtu_files(dir, "bar", mesh, *r, &written).ok());
  ASSERT_EQ(written.size(), 7u);  // six load cases and the .pvd that groups them
  EXPECT_EQ(std::filesystem::path(written[3]).filename(), "bar_Mx.vtu");
  EXPECT_EQ(std::filesystem::path(written[6]).filename(), "bar.pvd");

  for (int k = 0; k < 6; ++k) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(written[k].c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfPoints(), mesh.num_nodes());
    ASSERT_EQ(grid->GetNumberOfCells(), mesh.num_elements());
    EXPECT_EQ(grid->GetCellType(0), VTK_QUADRATIC_TETRA);
    auto* units = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("units"));
    ASSERT_NE(units, nullptr);
    EXPECT_EQ(units->GetValue(1), k < 3 ? "displacement: m per N" : "displacement: m per N m");
    vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
    vtkDataArray* vm = grid->GetCellData()->GetArray("von_mises");
    ASSERT_TRUE(u && vm);
    for (int i : {0, mesh.num_nodes() / 2, mesh.num_nodes() - 1})
      for (int c = 0; c < 3; ++c) EXPECT_EQ(u->GetComponent(i, c), r->displacement[k][i](c));
    if (k == 0) {
      // Unit axial force: away from the ends the stress is uniaxial, sigma = F / A, so von Mises
      // is 1 / (b h) Pa per N in the middle third of the bar.
      std::vector<double> middle;
      for (int e = 0; e < mesh.num_elements(); ++e) {
        const double x = mesh.nodes[mesh.element(e)[0]].x();
        if (x > L / 3 && x < 2 * L / 3) middle.push_back(vm->GetComponent(e, 0));
      }
      ASSERT_FALSE(middle.empty());
      const auto [lo, hi] = std::minmax_element(middle.begin(), middle.end());
      EXPECT_NEAR(*lo * b * h, 1.0, 0.01);
      EXPECT_NEAR(*hi * b * h, 1.0, 0.01);
      // A corner of the reference face moves by the axial compliance L / (E A) (to the FEA's 1 %).
      ASSERT_EQ(mesh.nodes[corner], Vec3(L, b / 2, h / 2));
      EXPECT_NEAR(r->displacement[0][corner].x() / (L / (210e9 * b * h)), 1.0, 0.02);
    }
  }
  std::filesystem::remove_all(dir);
}

TEST(FeaVtk, MissingFieldsAreReported) {
  const fea::TetMesh mesh = fea::make_box_mesh(Vec3::Zero(), Vec3::Ones(), 1, 1, 1);
  const Status s = write_link_vtu("/tmp/kinestat_none.vtu", mesh, fea::LinkStiffness{}, 0);
  EXPECT_EQ(s.code(), StatusCode::kInvalidInput);
  EXPECT_NE(s.message().find("keep_fields"), std::string::npos);
}

}  // namespace
}  // namespace kinestat::io
