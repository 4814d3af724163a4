#include "kinestat/io/orthoglide_results_json.hpp"

#include <cmath>

#include "io/json_values.hpp"
#include "kinestat/io/identification_yaml.hpp"
#include "kinestat/io/results_json.hpp"

namespace kinestat::io {
namespace {

using nlohmann::json;

// An infinite upper factor (a singularity inside the set) is written as null by encode_non_finite.
json range_json(const mechanisms::TransmissionRange& r) {
  return {{"min", r.min}, {"max", r.max}, {"singular", r.singular()}};
}

json search_json(const mechanisms::WorkspaceSearch& s) {
  return {{"range", range_json(s.range)},         {"p_at_min", to_array(s.p_at_min)},
          {"rho_at_min", to_array(s.rho_at_min)}, {"p_at_max", to_array(s.p_at_max)},
          {"rho_at_max", to_array(s.rho_at_max)}, {"evaluations", s.evaluations},
          {"singular_samples", s.singular}};
}

}  // namespace

json orthoglide_designs_to_json(const std::vector<mechanisms::OrthoglideDesign>& designs,
                                const std::vector<mechanisms::OrthoglideDesignCheck>& checks, int search_points) {
  json list = json::array();
  for (std::size_t i = 0; i < designs.size(); ++i) {
    const mechanisms::OrthoglideDesign& d = designs[i];
    json item = {{"strategy", d.strategy},
                 {"link_length", d.link_length},
                 {"rho_min", d.rho_min},
                 {"rho_max", d.rho_max},
                 {"p_min", d.p_min},
                 {"p_max", d.p_max},
                 {"rho_q_plus", d.rho_q_plus},
                 {"joint_sum_limit", std::isfinite(d.joint_sum_limit) ? json(d.joint_sum_limit) : json()},
                 {"transmission", {{"cube", range_json(d.cube)}, {"joint_space", range_json(d.joint_space)}}}};
    if (i < checks.size())
      item["check"] = {{"cube", search_json(checks[i].cube)}, {"joint_space", search_json(checks[i].joint_space)}};
    list.push_back(item);
  }
  json j = {{"schema", "kinestat-orthoglide-design"},
            {"schema_version", 1},
            {"units", {{"length", "m"}, {"transmission_factors", "-"}}},
            {"cube_size", designs.empty() ? 0.0 : designs.front().cube_size},
            {"mu", designs.empty() ? 0.0 : designs.front().mu},
            {"search_points", search_points},
            {"designs", list}};
  encode_non_finite(j);
  return j;
}

json identification_to_json(const std::vector<mechanisms::OrthoglideInput>& inputs,
                            const std::vector<mechanisms::ComplianceTarget>& targets,
                            const mechanisms::OrthoglideIdentification& id) {
  json in = json::array();
  for (std::size_t k = 0; k < inputs.size(); ++k)
    in.push_back({{"key", input_key(inputs[k])},
                  {"name", mechanisms::input_name(inputs[k])},
                  {"start", k < id.start_values.size() ? json(id.start_values[k]) : json()},
                  {"identified", k < id.values.size() ? json(id.values[k]) : json()}});
  json t = json::array();
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const mechanisms::ComplianceTarget& c = targets[k];
    const double rel = k < id.relative_residual.size() ? id.relative_residual[k] : std::nan("");
    t.push_back({{"label", c.label},
                 {"architecture", c.architecture == mechanisms::OrthoglideArchitecture::kPUU ? "3-PUU" : "3-PRPaR"},
                 {"point", to_array(c.point)},
                 {"row", c.row},
                 {"col", c.col},
                 {"target", c.value},
                 {"model", c.value + rel * std::abs(c.value)},
                 {"relative_residual", rel}});
  }
  json j = {{"schema", "kinestat-identification"},
            {"schema_version", 1},
            {"units",
             {{"inputs", "SI as named (N/m, m; bar section scale -)"},
              {"compliance", "m/N, 1/N (= m/(N m) = rad/N), rad/(N m) by row and column"},
              {"point", "m"}}},
            {"inputs", in},
            {"targets", t},
            {"iterations", id.iterations},
            {"evaluations", id.evaluations}};
  encode_non_finite(j);
  return j;
}

}  // namespace kinestat::io
