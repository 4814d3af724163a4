#include "kinestat/io/robot_design_output.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <vtkCellData.h>

#include "io/vti_image.hpp"
#include "kinestat/io/map_json.hpp"

namespace kinestat::io {
namespace {

using json = nlohmann::json;
using mechanisms::RobotDesignResult;
using mechanisms::RobotDesignSweep;

json number_or_null(double v) { return std::isnan(v) ? json(nullptr) : json(v); }

json design_to_json(const RobotDesignSweep& s, std::size_t k) {
  const RobotDesignResult& r = s.results.at(k);
  json j = {{"index", k},
            {"values", r.values},
            {"status", r.status.ok() ? "ok" : "failed"},
            {"reachable_measure", r.reachable_measure},
            {"stiff_measure", r.stiff_measure},
            {"reachable_points", r.reachable_points},
            {"stiff_points", r.stiff_points},
            {"k_t_min_worst", number_or_null(r.k_t_min_worst)}};
  if (!r.status.ok()) j["message"] = r.status.message();
  return j;
}

}  // namespace

json robot_design_sweep_to_json(const RobotDesignSweep& s, const std::string& robot, const std::string& units) {
  json j;
  j["schema"] = "kinestat-robot-design-sweep";
  j["version"] = 1;
  j["robot"] = robot;
  j["description"] = s.description;
  json params = json::array();
  for (std::size_t p = 0; p < s.parameters.size(); ++p)
    params.push_back({{"name", s.parameters[p].name},
                      {"lo", s.parameters[p].lo},
                      {"hi", s.parameters[p].hi},
                      {"values", mechanisms::design_values(s.parameters[p], s.dimensions[p])}});
  j["parameters"] = std::move(params);
  j["parameter_units"] = units;
  j["designs"] = {{"count", s.results.size()}, {"dimensions", s.dimensions}, {"order", "first parameter fastest"}};
  j["region"] = map_grid_to_json(s.region);
  j["criteria"] = {{"near_singular_threshold", s.near_singular_threshold},
                   {"min_stiffness", s.min_stiffness},
                   {"min_stiffness_unit", "N/m"},
                   {"min_stiffness_field", "k_t_min"},
                   {"score",
                    "stiff_measure: the region's area or volume where k_t_min >= min_stiffness; the best "
                    "design has the largest, of equal ones the first"}};
  j["measure_unit"] = s.volume() ? "m^3" : "m^2";
  json table = json::array();
  for (std::size_t k = 0; k < s.results.size(); ++k) table.push_back(design_to_json(s, k));
  j["designs_table"] = std::move(table);
  json best = design_to_json(s, s.best);
  json named = json::object();
  for (std::size_t p = 0; p < s.parameters.size(); ++p) named[s.parameters[p].name] = s.results.at(s.best).values[p];
  best["parameters"] = std::move(named);
  j["best"] = std::move(best);
  j["ranks"] = s.ranks;
  return j;
}

Status write_robot_design_sweep_vti(const std::string& path, const RobotDesignSweep& s, const std::string& units) {
  if (s.parameters.size() > 3)
    return Status::Invalid(
        fmt::format("{}: a VTI image has three axes; this sweep has {} parameters (write --json "
                    "instead)",
                    path, s.parameters.size()));
  // One cell per design, centred on its values: a design's value fills its cell.
  mechanisms::MapGrid cells;
  for (std::size_t p = 0; p < s.parameters.size(); ++p) {
    const mechanisms::DesignParameter& d = s.parameters[p];
    const int n = s.dimensions[p];
    const double spacing = n > 1 ? (d.hi - d.lo) / (n - 1) : (d.lo != 0.0 ? std::abs(d.lo) * 0.1 : 1.0);
    const int i = static_cast<int>(p);
    cells.spacing(i) = spacing;
    cells.origin(i) = d.lo - 0.5 * spacing;
    cells.dimensions[p] = n + 1;
  }
  auto image = make_vti_image(cells);
  std::vector<double> stiff, reachable, failed;
  for (const RobotDesignResult& r : s.results) {
    stiff.push_back(r.status.ok() ? r.stiff_measure : std::nan(""));
    reachable.push_back(r.status.ok() ? r.reachable_measure : std::nan(""));
    failed.push_back(r.status.ok() ? 0.0 : 1.0);
  }
  add_vti_cell_array(image, "stiff_measure", stiff);
  add_vti_cell_array(image, "reachable_measure", reachable);
  add_vti_cell_array(image, "failed", failed);
  const char* unit = s.volume() ? "m^3" : "m^2";
  add_vti_string(image, "stiff_measure_unit", unit);
  add_vti_string(image, "reachable_measure_unit", unit);
  image->GetCellData()->SetActiveScalars("stiff_measure");
  std::string axes;
  for (std::size_t p = 0; p < s.parameters.size(); ++p)
    axes += fmt::format("{}{}: {}", p ? ", " : "", "xyz"[p], s.parameters[p].name);
  add_vti_string(image, "axes", axes);
  add_vti_string(image, "parameter_units", units);
  add_vti_string(image, "description", s.description);
  return write_vti_image(path, image);
}

}  // namespace kinestat::io
