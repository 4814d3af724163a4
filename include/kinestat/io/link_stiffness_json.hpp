// The FEA link stiffness and its mesh-convergence study as JSON (schema "kinestat-link-stiffness",
// docs/results-json.md): SI units, stated in the document.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/mesh_convergence.hpp"

namespace kinestat::io {

// The 6x6 matrices, mesh, reference point, symmetry errors and eigenvalues of one analysis.
// `mesh_size` is the tetrahedron size (m); `from_cache` says the numbers come from the result cache.
nlohmann::json link_stiffness_to_json(const std::string& mesh_file, double mesh_size, const fea::LinkStiffness& r,
                                      bool from_cache);

// The study: per mesh its size (m), dofs and compliance diagonal; per dof the Richardson estimate or
// why there is none.
nlohmann::json convergence_study_to_json(const fea::ConvergenceStudy& study);

}  // namespace kinestat::io
