// Robot design-sweep files: the JSON has the parameters with their unit, every design (a failed one
// with its message, no k_t_min as null) and the best by name; the VTI read back has one cell per
// design centred on its values, the stiff measure active and NaN on a failed design; more than
// three parameters are refused for VTI.
#include "kinestat/io/robot_design_output.hpp"

#include <gtest/gtest.h>
#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkXMLImageDataReader.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace kinestat::io {
namespace {

using mechanisms::RobotDesignResult;
using mechanisms::RobotDesignSweep;

// arm 250, 350 x forearm 700, 800, 900 (arm fastest); design 1 failed, design 4 the best.
RobotDesignSweep sample() {
  RobotDesignSweep s;
  s.parameters = {{"arm", 250, 350}, {"forearm", 700, 900}};
  s.dimensions = {2, 3};
  auto grid = mechanisms::make_map_grid({mechanisms::MapRange{0, 0.2}, {0, 0.2}, {-0.9, -0.7}}, 0.1, 1000);
  s.region = *grid;
  s.description = "Delta (VJM, unloaded)";
  s.min_stiffness = 3e3;
  for (int k = 0; k < 6; ++k) {
    RobotDesignResult r;
    r.values = {k % 2 ? 350.0 : 250.0, 700.0 + 100.0 * (k / 2)};
    r.reachable_measure = 1e-3 * (k + 1);
    r.stiff_measure = k == 4 ? 5e-3 : 1e-3 * k / 2;
    r.reachable_points = static_cast<std::size_t>(k + 1);
    r.stiff_points = static_cast<std::size_t>(r.stiff_measure * 1e3);
    r.k_t_min_worst = k == 0 ? std::nan("") : 1e3 * k;
    if (k == 1) r = RobotDesignResult{r.values, Status::Invalid("height is not finite")};
    s.results.push_back(r);
  }
  s.best = 4;
  return s;
}

TEST(RobotDesignOutput, JsonHasEveryDesignTheBestAndTheUnit) {
  const nlohmann::json j = robot_design_sweep_to_json(sample(), "delta.yaml", "lengths in mm");
  EXPECT_EQ(j["schema"], "kinestat-robot-design-sweep");
  EXPECT_EQ(j["parameter_units"], "lengths in mm");
  EXPECT_EQ(j["measure_unit"], "m^3");
  EXPECT_EQ(j["parameters"][1]["values"], (std::vector<double>{700, 800, 900}));
  ASSERT_EQ(j["designs_table"].size(), 6u);
  EXPECT_EQ(j["designs_table"][1]["status"], "failed");
  EXPECT_EQ(j["designs_table"][1]["message"], "height is not finite");
  EXPECT_TRUE(j["designs_table"][0]["k_t_min_worst"].is_null());
  EXPECT_EQ(j["best"]["index"], 4);
  EXPECT_EQ(j["best"]["parameters"]["arm"], 250.0);
  EXPECT_EQ(j["best"]["parameters"]["forearm"], 900.0);
  EXPECT_DOUBLE_EQ(j["best"]["stiff_measure"].get<double>(), 5e-3);
  EXPECT_EQ(j["criteria"]["min_stiffness"], 3e3);
}

TEST(RobotDesignOutput, VtiHasOneCellPerDesign) {
  const RobotDesignSweep s = sample();
  const std::string path = ::testing::TempDir() + "kinestat_robot_design.vti";
  ASSERT_TRUE(write_robot_design_sweep_vti(path, s, "lengths in mm").ok());
  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  ASSERT_EQ(image->GetNumberOfCells(), 6);
  for (vtkIdType k = 0; k < 6; ++k) {  // cell k's centre is design k's (arm, forearm)
    double centre[3], pcoords[3], weights[8];
    vtkCell* cell = image->GetCell(k);
    int sub = cell->GetParametricCenter(pcoords);
    cell->EvaluateLocation(sub, pcoords, centre, weights);
    EXPECT_NEAR(centre[0], s.results[k].values[0], 1e-9) << k;
    EXPECT_NEAR(centre[1], s.results[k].values[1], 1e-9) << k;
  }
  vtkCellData* cd = image->GetCellData();
  ASSERT_NE(cd->GetScalars(), nullptr);
  EXPECT_STREQ(cd->GetScalars()->GetName(), "stiff_measure");
  EXPECT_TRUE(std::isnan(cd->GetArray("stiff_measure")->GetTuple1(1)));
  EXPECT_EQ(cd->GetArray("failed")->GetTuple1(1), 1.0);
  EXPECT_DOUBLE_EQ(cd->GetArray("stiff_measure")->GetTuple1(4), 5e-3);
  std::filesystem::remove(path);

  RobotDesignSweep four = s;
  four.parameters.push_back({"a", 1, 1});
  four.parameters.push_back({"b", 1, 1});
  four.dimensions = {2, 3, 1, 1};
  const Status refused = write_robot_design_sweep_vti(path, four, "");
  EXPECT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("three axes"), std::string::npos) << refused.message();
}

}  // namespace
}  // namespace kinestat::io
