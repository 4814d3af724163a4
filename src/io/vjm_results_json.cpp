#include "kinestat/io/vjm_results_json.hpp"

#include "io/json_values.hpp"
#include "kinestat/core/stiffness_indices.hpp"
#include "kinestat/io/results_json.hpp"

namespace kinestat::io {
namespace {

using nlohmann::json;

json twists(const std::vector<Vec6>& directions) {
  json a = json::array();
  for (const Vec6& d : directions) a.push_back({{"twist", to_array(d)}, {"description", describe_twist(d)}});
  return a;
}

json stiffness_json(const CartesianStiffness& K) {
  return {{"order", {"ux", "uy", "uz", "rx", "ry", "rz"}},
          {"stiffness", to_rows(K.stiffness)},
          {"stiffness_units", unit_matrix(false)},
          {"compliance_defined", K.compliance_defined},
          {"compliance", K.compliance_defined ? to_rows(K.compliance) : json()},
          {"compliance_units", unit_matrix(true)},
          {"indices", stiffness_indices_to_json(stiffness_indices(K.stiffness))},
          {"free_directions", twists(K.free_directions)},
          {"rigid_directions", twists(K.rigid_directions)},
          {"status", status_json(K.status)}};
}

}  // namespace

json vjm_results_to_json(const VjmResults& r) {
  json j = {{"schema", "kinestat-vjm-results"},
            {"schema_version", 1},
            {"units", {{"length", "m"}, {"force", "N"}, {"moment", "N m"}, {"angle", "rad"}}},
            {"model", {{"file", r.model_file}, {"title", r.title}, {"num_chains", r.num_chains}}},
            {"tool_point", to_array(r.tool_point)},
            {"unloaded", stiffness_json(r.unloaded)},
            {"loaded", json()}};
  if (r.state) {
    const vjm::ConvergenceReport& c = r.state->report;
    j["loaded"] = {{"displacement", to_array(r.state->displacement.head<3>())},
                   {"rotation", to_array(r.state->displacement.tail<3>())},
                   {"force", to_array(r.state->wrench.head<3>())},
                   {"moment", to_array(r.state->wrench.tail<3>())},
                   {"equilibrium",
                    {{"converged", c.converged},
                     {"method", c.method},
                     {"fixed_point_iterations", c.fixed_point_iterations},
                     {"newton_iterations", c.newton_iterations},
                     {"kinematic_residual", c.kinematic_residual},
                     {"static_residual", c.static_residual}}},
                   {"stiffness", r.loaded ? stiffness_json(*r.loaded) : json()}};
  }
  encode_non_finite(j);
  return j;
}

}  // namespace kinestat::io
