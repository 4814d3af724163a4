// MSA results as JSON (schema "kinestat-msa-results", documented field by field with units in
// docs/results-json.md). Non-finite numbers (an overflowed determinant, the condition number of a
// singular matrix) are written as null and listed under "non_finite_values".
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/core/stiffness_indices.hpp"
#include "kinestat/msa/buckling.hpp"
#include "kinestat/msa/modes.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::io {

// Bump when a field changes meaning or disappears (adding fields keeps the version).
inline constexpr int kResultsSchemaVersion = 1;

// Every result of an MSA solve: model summary, solver report, load cases, Cartesian stiffness,
// indices and singularity diagnosis. Ids refer to the structure's nodes, beams and joints:
// kInvalidInput (msa::check_solution_matches) for a solution of another structure.
// `stations` (msa::all_beam_stations, [case][beam]; null: none) adds each case's "beam_stations".
StatusOr<nlohmann::json> solution_to_json(const msa::Structure& s, const msa::Solution& sol,
                                          const std::vector<std::vector<msa::BeamStations>>* stations = nullptr);

// A buckling analysis (schema "kinestat-buckling-results", docs/results-json.md): the load case, the
// beams' axial forces, and per mode the load factor, its residual, the most compressed beam's
// critical axial force and the shape. kInvalidInput when its arrays do not match the structure.
StatusOr<nlohmann::json> buckling_to_json(const msa::Structure& s, const msa::BucklingResult& r);

// A modal analysis (schema "kinestat-modes-results", docs/results-json.md): total mass, and per mode
// the frequency, the participation factors and effective masses along x, y, z and the
// mass-normalized shape. kInvalidInput when its arrays do not match the structure.
StatusOr<nlohmann::json> modes_to_json(const msa::Structure& s, const msa::ModalResult& r, bool lumped);

// All fields of StiffnessIndices (eigenvectors as a list, eigenvectors[i] belonging to eigenvalues[i]).
// May hold non-finite numbers: pass the finished document through encode_non_finite.
nlohmann::json stiffness_indices_to_json(const StiffnessIndices& ind);

// Replaces every NaN/inf number in `j` by null and appends {"path": JSON pointer, "value": "inf",
// "-inf" or "nan"} to j["non_finite_values"] (created, possibly empty, when `j` is an object):
// JSON has no such numbers and a bare null would not say which one it was.
void encode_non_finite(nlohmann::json& j);

// Writes `j` indented by `indent` spaces (-1: compact, on one line), complete or not at all
// (core/atomic_file.hpp); kInvalidInput naming the path when it cannot be written.
Status write_json(const std::string& path, const nlohmann::json& j, int indent = 2);
// The same text to a stream (`--json -` writes to stdout).
void write_json(std::ostream& out, const nlohmann::json& j, int indent = 2);

}  // namespace kinestat::io
