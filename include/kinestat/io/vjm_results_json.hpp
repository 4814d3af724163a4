// VJM platform stiffness as JSON (schema "kinestat-vjm-results", docs/results-json.md): the unloaded
// stiffness (Pashkevich et al. 2009, eq. 10) and, under a load, the equilibrium and the loaded
// stiffness (eq. 21). SI units, stated in the document.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::io {

struct VjmResults {
  std::string model_file, title;
  int num_chains = 0;
  Vec3 tool_point = Vec3::Zero();  // m
  CartesianStiffness unloaded;
  std::optional<vjm::PlatformState> state;   // empty: no load given
  std::optional<CartesianStiffness> loaded;  // empty: no load, or its stiffness failed
};

nlohmann::json vjm_results_to_json(const VjmResults& r);

}  // namespace kinestat::io
