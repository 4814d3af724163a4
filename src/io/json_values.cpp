#include "io/json_values.hpp"

namespace kinestat::io {

nlohmann::json unit_matrix(bool compliance) {
  const char* per_force[2] = {"m/N", "rad/N"};
  const char* per_moment[2] = {"m/(N m)", "rad/(N m)"};
  const char* per_translation[2] = {"N/m", "N m/m"};
  const char* per_rotation[2] = {"N/rad", "N m/rad"};
  nlohmann::json rows = nlohmann::json::array();
  for (int i = 0; i < 6; ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (int j = 0; j < 6; ++j)
      row.push_back(compliance ? (j < 3 ? per_force : per_moment)[i / 3]
                               : (j < 3 ? per_translation : per_rotation)[i / 3]);
    rows.push_back(row);
  }
  return rows;
}

const char* status_name(StatusCode c) {
  switch (c) {
    case StatusCode::kOk:
      return "ok";
    case StatusCode::kInvalidInput:
      return "invalid_input";
    case StatusCode::kSingular:
      return "singular";
    case StatusCode::kNotConverged:
      return "not_converged";
    case StatusCode::kInternal:
      return "internal";
  }
  return "unknown";
}

nlohmann::json status_json(const Status& s) { return {{"code", status_name(s.code())}, {"message", s.message()}}; }

}  // namespace kinestat::io
