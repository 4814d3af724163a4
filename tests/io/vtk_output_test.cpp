// write_vtk: files read back with VTK's own XML reader hold the nodes, elements and results of the
// Solution; the .pvd collection lists them; a singular solution shows its free motions.
#include "kinestat/io/vtk_output.hpp"

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "kinestat/io/structure_yaml.hpp"
#include "sample_results.hpp"

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;

vtkSmartPointer<vtkUnstructuredGrid> read_vtu(const std::string& path) {
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  return grid;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class VtkOutput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        ::testing::TempDir() + "kinestat_vtk_test_" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string dir_;
};

TEST_F(VtkOutput, LoadCasesReadBackWithGeometryAndResults) {
  const msa::Structure s = io_test::sample_structure();
  const msa::Solution sol = io_test::sample_solution();
  std::vector<std::string> written;
  const Status st = write_vtk(s, sol, dir_, "sample", &written);
  ASSERT_TRUE(st.ok()) << st.message();
  ASSERT_EQ(written.size(), 3u);
  EXPECT_EQ(written[0], dir_ + "/sample_case1.vtu");
  EXPECT_EQ(written[1], dir_ + "/sample_case2.vtu");
  EXPECT_EQ(written[2], dir_ + "/sample.pvd");

  for (int c = 0; c < 2; ++c) {
    auto grid = read_vtu(written[static_cast<std::size_t>(c)]);
    ASSERT_EQ(grid->GetNumberOfPoints(), 4);
    for (int n = 0; n < 4; ++n) {
      double p[3];
      grid->GetPoint(n, p);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], s.nodes()[static_cast<std::size_t>(n)].position(k));
    }
    vtkDataArray* disp = grid->GetPointData()->GetArray("displacement");
    vtkDataArray* rot = grid->GetPointData()->GetArray("rotation");
    vtkDataArray* reaction = grid->GetPointData()->GetArray("reaction_moment");
    ASSERT_TRUE(disp && rot && reaction);
    ASSERT_EQ(disp->GetNumberOfComponents(), 3);
    for (int n = 0; n < 4; ++n) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(disp->GetComponent(n, k), io_test::sample_displacement(c, n, k));
        EXPECT_EQ(rot->GetComponent(n, k), io_test::sample_displacement(c, n, k + 3));
      }
    }
    EXPECT_EQ(reaction->GetComponent(0, 2), -6.0 - c);
    EXPECT_EQ(grid->GetPointData()->GetVectors()->GetName(), std::string("displacement"));

    // Cells: the beam, the joint (coincident nodes: a 2-point poly-vertex), the rigid link.
    ASSERT_EQ(grid->GetNumberOfCells(), 3);
    EXPECT_EQ(grid->GetCellType(0), VTK_LINE);
    EXPECT_EQ(grid->GetCellType(1), VTK_POLY_VERTEX);
    EXPECT_EQ(grid->GetCellType(2), VTK_LINE);
    EXPECT_EQ(grid->GetCell(2)->GetPointId(0), 2);
    EXPECT_EQ(grid->GetCell(2)->GetPointId(1), 3);
    vtkCellData* cd = grid->GetCellData();
    vtkDataArray* type = cd->GetArray("element_type");
    ASSERT_NE(type, nullptr);
    EXPECT_EQ(type->GetComponent(0, 0), kVtkBeam);
    EXPECT_EQ(type->GetComponent(1, 0), kVtkJoint);
    EXPECT_EQ(type->GetComponent(2, 0), kVtkRigidLink);
    EXPECT_EQ(cd->GetArray("element_id")->GetComponent(2, 0), 0);

    // Sample end forces (times the case number): N2 = 10, T2 = -3, |My| max 6, |Mz| max 7.
    const Vec12 f = io_test::sample_end_forces() * (c + 1);
    vtkDataArray* end = cd->GetArray("end_forces");
    ASSERT_EQ(end->GetNumberOfComponents(), 12);
    for (int k = 0; k < 12; ++k) EXPECT_EQ(end->GetComponent(0, k), f(k));
    EXPECT_EQ(cd->GetArray("axial_force")->GetComponent(0, 0), 10.0 * (c + 1));
    EXPECT_EQ(cd->GetArray("torsion")->GetComponent(0, 0), -3.0 * (c + 1));
    EXPECT_EQ(cd->GetArray("bending_moment_y")->GetComponent(0, 0), 6.0 * (c + 1));
    EXPECT_EQ(cd->GetArray("bending_moment_z")->GetComponent(0, 0), 7.0 * (c + 1));
    // Joint forces sit on the joint's cell only.
    vtkDataArray* joint = cd->GetArray("joint_force");
    EXPECT_EQ(joint->GetComponent(1, 5), 5.5 + c);
    EXPECT_EQ(joint->GetComponent(0, 5), 0.0);
    EXPECT_EQ(cd->GetArray("axial_force")->GetComponent(1, 0), 0.0);
  }

  const std::string pvd = read_text(written[2]);
  EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
  EXPECT_NE(pvd.find("timestep=\"0\" part=\"0\" name=\"first\" file=\"sample_case1.vtu\""), std::string::npos) << pvd;
  EXPECT_NE(pvd.find("name=\"second &lt;&amp;&gt;\" file=\"sample_case2.vtu\""), std::string::npos) << pvd;
}

TEST_F(VtkOutput, SingularSolutionShowsFreeMotionsOnTheUndeformedModel) {
  const msa::Structure s = io_test::sample_structure();
  const msa::Solution sol = io_test::sample_singular_solution();
  std::vector<std::string> written;
  ASSERT_TRUE(write_vtk(s, sol, dir_, "mech", &written).ok());
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], dir_ + "/mech_undeformed.vtu");
  auto grid = read_vtu(written[0]);
  EXPECT_EQ(grid->GetNumberOfPoints(), 4);
  EXPECT_EQ(grid->GetNumberOfCells(), 3);
  EXPECT_EQ(grid->GetPointData()->GetArray("displacement"), nullptr);
  vtkDataArray* mode = grid->GetPointData()->GetArray("free_motion_1");
  vtkDataArray* mode_rot = grid->GetPointData()->GetArray("free_motion_1_rotation");
  ASSERT_TRUE(mode && mode_rot);
  EXPECT_EQ(mode->GetComponent(3, 0), -0.5);
  EXPECT_EQ(mode->GetComponent(0, 0), 0.0);
  EXPECT_EQ(mode_rot->GetComponent(2, 2), 1.0);
  EXPECT_EQ(grid->GetPointData()->GetVectors()->GetName(), std::string("free_motion_1"));
  EXPECT_NE(read_text(written[1]).find("file=\"mech_undeformed.vtu\""), std::string::npos);
}

TEST_F(VtkOutput, UnwritableDirectoryIsReported) {
  fs::create_directories(dir_);
  const std::string blocker = dir_ + "/a_file";
  std::ofstream(blocker) << "x";
  const Status st = write_vtk(io_test::sample_structure(), io_test::sample_solution(), blocker + "/out", "x", nullptr);
  EXPECT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_EQ(st.message().rfind(blocker + "/out: ", 0), 0u) << st.message();
}

// A solution of another structure is bad input (msa::check_solution_matches), refused before any file.
TEST_F(VtkOutput, MismatchedSolutionIsRefused) {
  msa::Solution sol = io_test::sample_solution();
  sol.cases[0].displacement.pop_back();
  const Status st = write_vtk(io_test::sample_structure(), sol, dir_, "x", nullptr);
  EXPECT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_NE(st.message().find("displacements"), std::string::npos) << st.message();
  EXPECT_FALSE(fs::exists(fs::path(dir_) / "x.pvd"));
}

msa::Structure bundled(const std::string& name) {
  auto r = read_structure_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/" + name);
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? std::move(r).value() : msa::Structure{};
}

// End to end with the solver: every node's displacement in the file is the Solution's.
TEST_F(VtkOutput, PortalFrameSolutionReadsBack) {
  const msa::Structure s = bundled("portal_frame.yaml");
  const msa::Solution sol = msa::solve(s);
  ASSERT_TRUE(sol.status.ok()) << sol.status.message();
  std::vector<std::string> written;
  ASSERT_TRUE(write_vtk(s, sol, dir_, "portal", &written).ok());
  ASSERT_EQ(written.size(), sol.cases.size() + 1);
  for (std::size_t c = 0; c < sol.cases.size(); ++c) {
    auto grid = read_vtu(written[c]);
    ASSERT_EQ(grid->GetNumberOfPoints(), 4);
    ASSERT_EQ(grid->GetNumberOfCells(), 3);
    vtkDataArray* disp = grid->GetPointData()->GetArray("displacement");
    for (int n = 0; n < 4; ++n) {
      for (int k = 0; k < 3; ++k)
        EXPECT_EQ(disp->GetComponent(n, k), sol.cases[c].displacement[static_cast<std::size_t>(n)](k));
    }
    // Each file names its load case, and carries the warp factor that draws the largest
    // displacement as a tenth of the model's size (issue 21).
    auto* name = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("load_case"));
    ASSERT_NE(name, nullptr);
    EXPECT_EQ(name->GetValue(0), sol.cases[c].name);
    vtkDataArray* warp = grid->GetFieldData()->GetArray("warp_factor");
    ASSERT_NE(warp, nullptr);
    EXPECT_DOUBLE_EQ(warp->GetTuple1(0) * sol.cases[c].max_translation, 0.1 * s.length_scale());
  }
}

// The singular bundled model: the undeformed file carries the solver's free motion.
TEST_F(VtkOutput, ReleasedChainFreeMotionReadsBack) {
  const msa::Structure s = bundled("released_chain.yaml");
  const msa::Solution sol = msa::solve(s);
  ASSERT_EQ(sol.status.code(), StatusCode::kSingular);
  ASSERT_FALSE(sol.singularity.modes.empty());
  std::vector<std::string> written;
  ASSERT_TRUE(write_vtk(s, sol, dir_, "chain", &written).ok());
  auto grid = read_vtu(written.at(0));
  EXPECT_EQ(grid->GetCellType(2), VTK_POLY_VERTEX);  // the hinge joins two coincident nodes
  vtkDataArray* mode = grid->GetPointData()->GetArray("free_motion_1");
  ASSERT_NE(mode, nullptr);
  for (int n = 0; n < 4; ++n) {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(mode->GetComponent(n, k), sol.singularity.modes[0].node_motion[static_cast<std::size_t>(n)](k));
  }
}

}  // namespace
}  // namespace kinestat::io

namespace kinestat::io {
namespace {

// The cantilever's internal-force diagrams: 5 stations on one polyline; under the tip load P along
// y the moment on the +x face of [0, x] is that of the load about the cut, (L - x) e_x x P e_y:
// Mz(x) = P (L - x) (statics, exact), and the diagram vector is Mz e_y, e_y the local y axis
// (global y here).
TEST(VtkDiagrams, CantileverMomentDiagramReadsBack) {
  const std::string dir = ::testing::TempDir() + "kinestat_vtk_diagrams";
  std::filesystem::remove_all(dir);
  auto s = read_structure_yaml(std::string(KINESTAT_SOURCE_DIR) + "/models/cantilever.yaml");
  ASSERT_TRUE(s.ok());
  const msa::Solution sol = msa::solve(*s);
  ASSERT_TRUE(sol.status.ok());
  auto stations = msa::all_beam_stations(*s, sol, 5);
  ASSERT_TRUE(stations.ok());
  std::vector<std::string> written;
  ASSERT_TRUE(write_beam_diagrams_vtk(*s, sol, *stations, dir, "cantilever", &written).ok());
  ASSERT_EQ(written.size(), sol.cases.size() + 1);
  EXPECT_EQ(written.back(), dir + "/cantilever_diagram.pvd");
  auto grid = read_vtu(written[1]);  // tip_sideways: 500 N along y at x = L = 1 m
  ASSERT_EQ(grid->GetNumberOfPoints(), 5);
  ASSERT_EQ(grid->GetNumberOfCells(), 1);
  vtkDataArray* mz = grid->GetPointData()->GetArray("Mz");
  vtkDataArray* diagram = grid->GetPointData()->GetArray("Mz_diagram");
  ASSERT_NE(mz, nullptr);
  ASSERT_NE(diagram, nullptr);
  for (int i = 0; i < 5; ++i) {
    const double x = grid->GetPoint(i)[0];
    EXPECT_NEAR(x, 0.25 * i, 1e-15);
    EXPECT_NEAR(mz->GetTuple1(i), 500.0 * (1.0 - x), 1e-9);
    EXPECT_NEAR(diagram->GetComponent(i, 1), mz->GetTuple1(i), 1e-12);
    EXPECT_EQ(diagram->GetComponent(i, 0), 0.0);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kinestat::io
