// Orthoglide design strategies and input identification as JSON (schemas "kinestat-orthoglide-design"
// and "kinestat-identification", docs/results-json.md). SI units, stated in the documents.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "kinestat/mechanisms/orthoglide_design.hpp"
#include "kinestat/mechanisms/orthoglide_identification.hpp"

namespace kinestat::io {

// Each design with its numerical check (checks[i] of designs[i], made with `search_points` per edge).
nlohmann::json orthoglide_designs_to_json(const std::vector<mechanisms::OrthoglideDesign>& designs,
                                          const std::vector<mechanisms::OrthoglideDesignCheck>& checks,
                                          int search_points);

// The identified inputs (start and identified values) and each target against the identified model.
nlohmann::json identification_to_json(const std::vector<mechanisms::OrthoglideInput>& inputs,
                                      const std::vector<mechanisms::ComplianceTarget>& targets,
                                      const mechanisms::OrthoglideIdentification& id);

}  // namespace kinestat::io
