#include "kinestat/io/map_json.hpp"

#include <cmath>

namespace kinestat::io {
namespace {

using json = nlohmann::json;
using namespace kinestat::mechanisms;

// A number, or null where there is none (NaN: no value at this point) or it is infinite (a rigid
// direction: JSON has no infinity).
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json vec3(const Vec3& v) { return json::array({number(v.x()), number(v.y()), number(v.z())}); }

}  // namespace

json map_grid_to_json(const MapGrid& g) {
  return {{"origin", vec3(g.origin)},
          {"spacing", vec3(g.spacing)},
          {"dimensions", g.dimensions},
          {"num_points", g.num_points()},
          {"units", g.angular[0] || g.angular[1] || g.angular[2] ? "per axis (axis_units)" : "m"},
          {"axis_names", {g.names[0], g.names[1], g.names[2]}},
          {"axis_units", {axis_unit(g, 0), axis_unit(g, 1), axis_unit(g, 2)}},
          {"order", "x fastest: point i + nx (j + ny k) is origin + (i dx, j dy, k dz)"}};
}

json workspace_map_to_json(const WorkspaceMap& map) {
  const MapGrid& g = map.grid;
  json j;
  j["schema"] = "kinestat-workspace-map";
  j["version"] = kMapSchemaVersion;
  j["description"] = map.description;
  j["grid"] = map_grid_to_json(g);

  json fields = json::object(), units = json::object(), field_summary = json::object();
  for (const FieldValues& f : map.fields) {
    const MapFieldInfo& info = field_info(f.field);
    json values = json::array();
    for (double v : f.values) values.push_back(number(v));
    fields[info.name] = std::move(values);
    units[info.name] = info.unit;
    const FieldSummary& s = f.summary;
    field_summary[info.name] = {{"count", s.count},       {"min", number(s.min)},     {"max", number(s.max)},
                                {"mean", number(s.mean)}, {"argmin", vec3(s.argmin)}, {"unit", info.unit}};
  }
  j["fields"] = std::move(fields);
  j["units"] = std::move(units);

  json status = json::array(), codes = json::object(), counts = json::object();
  for (PostureStatus s : map.status) status.push_back(static_cast<int>(s));
  for (int s = 0; s < kNumPostureStatuses; ++s) {
    codes[std::to_string(s)] = to_string(static_cast<PostureStatus>(s));
    counts[to_string(static_cast<PostureStatus>(s))] = map.status_counts[s];
  }
  j["status"] = std::move(status);
  j["status_codes"] = std::move(codes);

  const std::string measure = measure_unit(g);
  json summary = {{"fields", std::move(field_summary)},
                  {"status_counts", std::move(counts)},
                  {"near_singular_threshold", map.near_singular_threshold},
                  {"reachable", {{"value", map.reachable_measure}, {"unit", measure}}}};
  if (map.min_stiffness)
    summary["stiff"] = {{"min_stiffness", *map.min_stiffness},
                        {"min_stiffness_unit", "N/m"},
                        {"value", map.stiff_measure},
                        {"unit", measure},
                        {"meaning", "points with values and k_t_min >= min_stiffness"}};
  j["summary"] = std::move(summary);

  json curves = json::object();
  for (const MapCurve& c : map.curves) {
    json lines = json::array();
    for (const std::vector<Vec3>& line : c.lines) {
      json points = json::array();
      for (const Vec3& p : line) points.push_back(vec3(p));
      lines.push_back(std::move(points));
    }
    curves[c.label] = std::move(lines);
  }
  j["curves"] = std::move(curves);
  return j;
}

}  // namespace kinestat::io
