#include "kinestat/io/five_bar_design_output.hpp"

#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <vtkCellData.h>

#include "io/vti_image.hpp"
#include "kinestat/io/map_json.hpp"

namespace kinestat::io {
namespace {

using json = nlohmann::json;
using mechanisms::FiveBarDesignSweep;
using mechanisms::kDesignShares;

std::vector<double> shares(const FiveBarDesignSweep& s, std::size_t mechanisms::FiveBarDesignResult::*count) {
  std::vector<double> out;
  for (const auto& r : s.results) out.push_back(s.share(r.*count));
  return out;
}

}  // namespace

json design_sweep_to_json(const FiveBarDesignSweep& s) {
  json j;
  j["schema"] = "kinestat-five-bar-design-sweep";
  j["version"] = 1;
  j["description"] = s.description;
  j["designs"] = map_grid_to_json(s.designs);
  j["designs"]["axes"] = {{"x", "r1 (proximal link length A_iB_i)"}, {"y", "r2 (distal link length B_iP)"}};
  j["region"] = map_grid_to_json(s.region);
  j["criteria"] = {{"near_singular_threshold", s.near_singular_threshold},
                   {"min_stiffness", s.min_stiffness ? json(*s.min_stiffness) : json(nullptr)},
                   {"min_stiffness_unit", "N/m"},
                   {"min_stiffness_field", "k_t_min"}};
  json fields = json::object(), units = json::object(), meaning = json::object(), r1 = json::array(),
       r2 = json::array();
  for (const auto& r : s.results) r1.push_back(r.r1), r2.push_back(r.r2);
  fields["r1"] = std::move(r1);
  fields["r2"] = std::move(r2);
  units["r1"] = units["r2"] = "m";
  for (const auto& info : kDesignShares) {
    fields[info.name] = shares(s, info.count);
    units[info.name] = "1";
    meaning[info.name] = info.meaning;
  }
  json worst = json::array();
  for (const auto& r : s.results) worst.push_back(std::isnan(r.k_t_min_worst) ? json(nullptr) : json(r.k_t_min_worst));
  fields["k_t_min_worst"] = std::move(worst);
  units["k_t_min_worst"] = "N/m";
  meaning["k_t_min_worst"] = "smallest k_t_min over the singularity-free points (null: none); breaks ties of the share";
  j["fields"] = std::move(fields);
  j["units"] = std::move(units);
  j["meaning"] = std::move(meaning);
  const auto& b = s.results.at(s.best);
  json best = {{"index", s.best},
               {"r1", b.r1},
               {"r2", b.r2},
               {"k_t_min_worst", std::isnan(b.k_t_min_worst) ? json(nullptr) : json(b.k_t_min_worst)}};
  for (const auto& info : kDesignShares) best[info.name] = s.share(b.*info.count);
  j["best"] = std::move(best);
  return j;
}

Status write_design_sweep_vti(const std::string& path, const FiveBarDesignSweep& s) {
  // One cell per design, centred on its (r1, r2): a design's value fills its cell instead of being
  // blended with its neighbours' across a cell, as point data would be.
  mechanisms::MapGrid cells = s.designs;
  for (int i = 0; i < 2; ++i) {
    cells.origin(i) -= 0.5 * cells.spacing(i);
    cells.dimensions[i] += 1;
  }
  auto image = make_vti_image(cells);
  for (const auto& info : kDesignShares) {
    add_vti_cell_array(image, info.name, shares(s, info.count));
    add_vti_string(image, fmt::format("{}_unit", info.name), "1");
  }
  std::vector<double> worst;
  for (const auto& r : s.results) worst.push_back(r.k_t_min_worst);
  add_vti_cell_array(image, "k_t_min_worst", worst);
  add_vti_string(image, "k_t_min_worst_unit", "N/m");
  image->GetCellData()->SetActiveScalars(kDesignShares[2].name);  // the share the best design is chosen by
  add_vti_string(image, "length_unit", "m");
  add_vti_string(image, "axes", "x: r1, y: r2 (m)");
  add_vti_string(image, "description", s.description);
  return write_vti_image(path, image);
}

}  // namespace kinestat::io
