// Workspace maps written as VTI (read back with VTK's reader) and as JSON.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataReader.h>

#include "kinestat/io/map_json.hpp"
#include "kinestat/io/map_vti.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/five_bar_loci.hpp"

namespace kinestat::io {
namespace {

using namespace kinestat::mechanisms;

// A small five-bar map under a load (every field), with reachable and unreachable points and its loci.
WorkspaceMap small_map() {
  FiveBarKernelOptions o;
  o.load << 1.0, 2.0, 0.0, 0.0, 0.0, 0.1;
  auto grid = make_map_grid({MapRange{-0.15, 0.15}, MapRange{0.0, 0.2}, MapRange{}}, 0.05, 1000);
  MapOptions mo;
  mo.with_deflection = true;
  mo.min_stiffness = 1e4;
  auto map = compute_workspace_map(*make_reference_five_bar_kernel(o), *grid, mo);
  EXPECT_TRUE(map.ok());
  map->curves = five_bar_singular_loci(o.params, o.mode, o.assembly, 64);
  return *map;
}

TEST(MapVti, ReadBackWithVtkGridArraysStatusAndHiddenPoints) {
  const WorkspaceMap map = small_map();
  ASSERT_EQ(map.fields.size(), static_cast<std::size_t>(kNumMapFields - 1));  // all but newton_iterations
  ASSERT_GT(map.status_counts[static_cast<int>(PostureStatus::kUnreachable)], 0u);
  ASSERT_GT(map.status_counts[static_cast<int>(PostureStatus::kOk)], 0u);
  const std::string path = (std::filesystem::temp_directory_path() / "kinestat_map_test.vti").string();
  ASSERT_TRUE(write_map_vti(path, map).ok());

  vtkNew<vtkXMLImageDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 7);
  EXPECT_EQ(dims[1], 5);
  EXPECT_EQ(dims[2], 1);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[0], -0.15);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 0.05);
  const vtkIdType n = image->GetNumberOfPoints();
  ASSERT_EQ(n, 35);

  vtkPointData* pd = image->GetPointData();
  vtkDataArray* status = pd->GetArray("status");
  vtkDataArray* ghost = pd->GetArray(vtkDataSetAttributes::GhostArrayName());
  ASSERT_TRUE(status && ghost);
  for (const FieldValues& f : map.fields) {
    vtkDataArray* a = pd->GetArray(vti_array_name(f.field).c_str());
    ASSERT_NE(a, nullptr) << vti_array_name(f.field);
    for (vtkIdType i = 0; i < n; ++i) {
      const double v = a->GetComponent(i, 0);
      if (std::isnan(f.values[i])) {
        EXPECT_TRUE(std::isnan(v)) << vti_array_name(f.field) << " " << i;  // masked, never a filler
      } else {
        EXPECT_EQ(v, f.values[i]);
      }
    }
  }
  // Names ParaView's Calculator takes unquoted; units beside them; k_t_min colours the map on opening.
  EXPECT_NE(pd->GetArray("k_t_min"), nullptr);
  EXPECT_NE(pd->GetArray("deflection_r"), nullptr);
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
    EXPECT_EQ(std::string(pd->GetArrayName(i)).find_first_of(" ()/"), std::string::npos) << pd->GetArrayName(i);
  ASSERT_NE(pd->GetScalars(), nullptr);
  EXPECT_STREQ(pd->GetScalars()->GetName(), "k_t_min");
  auto* kunit = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("k_t_min_unit"));
  ASSERT_NE(kunit, nullptr);
  EXPECT_EQ(kunit->GetValue(0), "N/m");
  // A cell is hidden exactly when one of its corners is.
  vtkDataArray* hidden_cells = image->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  ASSERT_NE(hidden_cells, nullptr);
  ASSERT_EQ(hidden_cells->GetNumberOfTuples(), image->GetNumberOfCells());
  for (vtkIdType c = 0; c < image->GetNumberOfCells(); ++c) {
    vtkNew<vtkIdList> corners;
    image->GetCellPoints(c, corners);
    bool masked = false;
    for (vtkIdType k = 0; k < corners->GetNumberOfIds(); ++k) masked |= !has_values(map.status[corners->GetId(k)]);
    EXPECT_EQ(hidden_cells->GetComponent(c, 0), masked ? vtkDataSetAttributes::HIDDENCELL : 0) << c;
  }
  for (vtkIdType i = 0; i < n; ++i) {
    EXPECT_EQ(status->GetComponent(i, 0), static_cast<double>(map.status[i]));
    const int hidden = vtkDataSetAttributes::HIDDENPOINT;
    EXPECT_EQ(ghost->GetComponent(i, 0), has_values(map.status[i]) ? 0 : hidden);
    if (map.status[i] == PostureStatus::kUnreachable) {
      EXPECT_TRUE(std::isnan(pd->GetArray("k_t_min")->GetComponent(i, 0)));
    }
  }
  auto* unit = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("length_unit"));
  ASSERT_NE(unit, nullptr);
  EXPECT_EQ(unit->GetValue(0), "m");
  auto* codes = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("status_values"));
  ASSERT_NE(codes, nullptr);
  EXPECT_EQ(codes->GetValue(0), "0 ok, 1 unreachable, 2 singular, 3 failed, 4 near-singular");
  std::filesystem::remove(path);
}

TEST(MapJson, FlatFieldsWithNullsGridSummaryAndCurves) {
  const WorkspaceMap map = small_map();
  const nlohmann::json j = workspace_map_to_json(map);
  EXPECT_EQ(j["schema"], "kinestat-workspace-map");
  EXPECT_EQ(j["grid"]["dimensions"], nlohmann::json::array({7, 5, 1}));
  EXPECT_EQ(j["grid"]["spacing"][0], 0.05);
  EXPECT_EQ(j["grid"]["units"], "m");
  EXPECT_EQ(j["units"]["k_r_min"], "N m/rad");
  const auto& kt = j["fields"]["k_t_min"];
  ASSERT_EQ(kt.size(), 35u);
  const std::vector<double>& values = map.find(MapField::kTranslationalMin)->values;
  for (std::size_t i = 0; i < values.size(); ++i) {
    EXPECT_EQ(j["status"][i], static_cast<int>(map.status[i]));
    if (std::isnan(values[i])) {
      EXPECT_TRUE(kt[i].is_null()) << i;
    } else {
      EXPECT_EQ(kt[i].get<double>(), values[i]);
    }
  }
  // Round trip through text keeps the numbers (17 significant digits).
  const nlohmann::json back = nlohmann::json::parse(j.dump());
  EXPECT_EQ(back["fields"]["deflection_t"], j["fields"]["deflection_t"]);
  const auto& s = j["summary"]["fields"]["k_t_min"];
  EXPECT_EQ(s["min"].get<double>(), map.find(MapField::kTranslationalMin)->summary.min);
  EXPECT_EQ(s["argmin"].size(), 3u);
  EXPECT_EQ(j["summary"]["status_counts"]["unreachable"], map.status_counts[1]);
  EXPECT_EQ(j["summary"]["reachable"]["unit"], "m^2");
  EXPECT_EQ(j["summary"]["stiff"]["value"].get<double>(), map.stiff_measure);
  EXPECT_EQ(j["status_codes"]["4"], "near-singular");
  ASSERT_TRUE(j["curves"].contains("parallel singularity"));
  EXPECT_FALSE(j["curves"]["workspace boundary"].empty());
  EXPECT_EQ(j["curves"]["workspace boundary"][0][0].size(), 3u);
}

}  // namespace
}  // namespace kinestat::io
