// Design-sweep files: the VTI read back with VTK's reader has the design grid and the three shares;
// the JSON has the grids, the shares per design (r1 fastest) and the best design.
#include "kinestat/io/five_bar_design_output.hpp"

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace kinestat::io {
namespace {

using mechanisms::FiveBarDesignSweep;

// 3 x 2 designs over a region of 10 points; design 4 (r1 index 1, r2 index 1) is the best.
FiveBarDesignSweep sample_sweep() {
  FiveBarDesignSweep s;
  s.designs.origin = Vec3(0.05, 0.08, 0.0);
  s.designs.spacing = Vec3(0.01, 0.02, 1e-3);
  s.designs.dimensions = {3, 2, 1};
  s.region.origin = Vec3(-0.01, 0.1, 0.0);
  s.region.spacing = Vec3(0.005, 0.005, 0.005);
  s.region.dimensions = {5, 2, 1};
  s.description = "five-bar ++ up (MSA)";
  s.near_singular_threshold = 0.01;
  s.min_stiffness = 2e4;
  for (std::size_t k = 0; k < 6; ++k) {
    const Vec3 p = s.designs.point(k);
    s.results.push_back({p.x(), p.y(), 10 - k % 3, 8 - k % 3, k});
    if (k != 2) s.results.back().k_t_min_worst = 1000.0 * static_cast<double>(k + 1);  // design 2: none
  }
  s.results[5].stiff = 2;
  s.best = 4;
  return s;
}

TEST(FiveBarDesignOutput, VtiReadBackHasTheDesignGridAndShares) {
  const FiveBarDesignSweep s = sample_sweep();
  const std::string path = ::testing::TempDir() + "kinestat_design_sweep.vti";
  ASSERT_TRUE(write_design_sweep_vti(path, s).ok());
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  // x: r1, y: r2 (m). One cell per design, centred on it (half a spacing each side), so ParaView
  // paints each design's value over its own cell instead of blending neighbours (issue 21).
  const int* dims = image->GetDimensions();
  EXPECT_EQ(std::vector<int>(dims, dims + 3), (std::vector<int>{4, 3, 1}));
  EXPECT_DOUBLE_EQ(image->GetOrigin()[0], 0.05 - 0.005);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[1], 0.08 - 0.01);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 0.02);
  ASSERT_EQ(image->GetNumberOfCells(), 6);
  for (vtkIdType k = 0; k < 6; ++k) {  // cell k's centre is design k's (r1, r2)
    double centre[3], pcoords[3], weights[8];
    int sub = 0;
    vtkCell* cell = image->GetCell(k);
    sub = cell->GetParametricCenter(pcoords);
    cell->EvaluateLocation(sub, pcoords, centre, weights);
    EXPECT_NEAR(centre[0], s.results[k].r1, 1e-12) << k;
    EXPECT_NEAR(centre[1], s.results[k].r2, 1e-12) << k;
  }
  vtkCellData* cd = image->GetCellData();
  vtkDataArray* share = cd->GetArray("share");
  vtkDataArray* reachable = cd->GetArray("reachable_share");
  ASSERT_NE(share, nullptr);
  ASSERT_NE(reachable, nullptr);
  ASSERT_NE(cd->GetArray("singularity_free_share"), nullptr);
  ASSERT_NE(cd->GetScalars(), nullptr);
  EXPECT_STREQ(cd->GetScalars()->GetName(), "share");  // what ParaView colours by on opening
  for (vtkIdType k = 0; k < 6; ++k) {
    EXPECT_DOUBLE_EQ(share->GetTuple1(k), static_cast<double>(s.results[k].stiff) / 10.0);
    EXPECT_DOUBLE_EQ(reachable->GetTuple1(k), static_cast<double>(s.results[k].reachable) / 10.0);
  }
  vtkDataArray* worst = cd->GetArray("k_t_min_worst");
  ASSERT_NE(worst, nullptr);
  EXPECT_DOUBLE_EQ(worst->GetTuple1(0), 1000.0);
  EXPECT_TRUE(std::isnan(worst->GetTuple1(2)));  // no value stays NaN, never a filler
  std::filesystem::remove(path);
}

TEST(FiveBarDesignOutput, JsonHasGridsSharesAndTheBestDesign) {
  const FiveBarDesignSweep s = sample_sweep();
  const nlohmann::json j = design_sweep_to_json(s);
  EXPECT_EQ(j["schema"], "kinestat-five-bar-design-sweep");
  EXPECT_EQ(j["designs"]["dimensions"], nlohmann::json::array({3, 2, 1}));
  EXPECT_EQ(j["region"]["num_points"], 10);
  EXPECT_DOUBLE_EQ(j["criteria"]["min_stiffness"].get<double>(), 2e4);
  ASSERT_EQ(j["fields"]["share"].size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) {
    EXPECT_DOUBLE_EQ(j["fields"]["r1"][k].get<double>(), 0.05 + 0.01 * static_cast<double>(k % 3));
    EXPECT_DOUBLE_EQ(j["fields"]["r2"][k].get<double>(), 0.08 + 0.02 * static_cast<double>(k / 3));
    EXPECT_DOUBLE_EQ(j["fields"]["singularity_free_share"][k].get<double>(),
                     static_cast<double>(s.results[k].singularity_free) / 10.0);
  }
  EXPECT_EQ(j["best"]["index"], 4);
  EXPECT_DOUBLE_EQ(j["best"]["r1"].get<double>(), 0.06);
  EXPECT_DOUBLE_EQ(j["best"]["r2"].get<double>(), 0.10);
  EXPECT_DOUBLE_EQ(j["best"]["share"].get<double>(), 0.4);
  EXPECT_EQ(j["units"]["share"], "1");
  EXPECT_DOUBLE_EQ(j["fields"]["k_t_min_worst"][5].get<double>(), 6000.0);
  EXPECT_TRUE(j["fields"]["k_t_min_worst"][2].is_null());
  EXPECT_EQ(j["units"]["k_t_min_worst"], "N/m");
  EXPECT_DOUBLE_EQ(j["best"]["k_t_min_worst"].get<double>(), 5000.0);
}

TEST(FiveBarDesignOutput, UnwritableVtiPathIsNamed) {
  const std::string path = ::testing::TempDir() + "no/such/dir/design.vti";
  const Status st = write_design_sweep_vti(path, sample_sweep());
  EXPECT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_NE(st.message().find(path), std::string::npos);
}

}  // namespace
}  // namespace kinestat::io
