// Building blocks of kinestat's JSON documents (internal to io): vectors, matrices by rows, the
// unit of each entry of a 6x6 compliance or stiffness, and a Status.
#pragma once

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "kinestat/core/status.hpp"

namespace kinestat::io {

template <class Derived>
nlohmann::json to_array(const Eigen::DenseBase<Derived>& v) {
  nlohmann::json a = nlohmann::json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(v(i));
  return a;
}

template <class Derived>
nlohmann::json to_rows(const Eigen::DenseBase<Derived>& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) rows.push_back(to_array(m.row(r)));
  return rows;
}

// Unit of entry (i, j) of the 6x6 compliance (motion per wrench: m/N, m/(N m), rad/N, rad/(N m)) or
// stiffness (wrench per motion: N/m, N/rad, N m/m, N m/rad), dofs ux uy uz rx ry rz.
nlohmann::json unit_matrix(bool compliance);

// "ok", "invalid_input", "singular", "not_converged" or "internal".
const char* status_name(StatusCode c);

// {"code": status_name, "message": the reason in words, empty when ok}.
nlohmann::json status_json(const Status& s);

}  // namespace kinestat::io
