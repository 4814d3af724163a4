#include "kinestat/io/link_stiffness_json.hpp"

#include "io/json_values.hpp"
#include "kinestat/io/results_json.hpp"

namespace kinestat::io {

using nlohmann::json;

json link_stiffness_to_json(const std::string& mesh_file, double mesh_size, const fea::LinkStiffness& r,
                            bool from_cache) {
  json j = {
      {"schema", "kinestat-link-stiffness"},
      {"version", 1},
      {"units",
       {{"length", "m"},
        {"force", "N"},
        {"moment", "N m"},
        {"angle", "rad"},
        {"stress", "Pa"},
        {"dofs", "ux uy uz rx ry rz in the mesh (link) frame"}}},
      {"mesh",
       {{"file", mesh_file},
        {"size_m", mesh_size},
        {"nodes", r.num_nodes},
        {"elements", r.num_elements},
        {"nodes_per_element", r.nodes_per_element},
        {"dofs", r.num_dofs}}},
      {"from_cache", from_cache},
      {"reference_model", fea::reference_model_name(r.reference_model)},
      {"reference_point_m", to_array(r.cartesian.point)},
      {"stiffness", to_rows(r.cartesian.stiffness)},
      {"stiffness_units", unit_matrix(false)},
      {"compliance", to_rows(r.cartesian.compliance)},
      {"compliance_units", unit_matrix(true)},
      {"symmetry_error", {{"compliance", r.compliance_symmetry_error}, {"stiffness", r.stiffness_symmetry_error}}},
      {"eigenvalues_SI_mixed_units",
       {{"stiffness", r.cartesian.indices ? to_array(r.cartesian.indices->eigenvalues) : json::array()},
        {"compliance", to_array(r.compliance_eigenvalues)}}}};
  if (!r.backend.empty()) {  // a computed result (not read from the cache): how it was solved
    const auto& f = r.factorization;
    j["solver"] = {{"backend", r.backend},
                   {"ordering", f.ordering},
                   {"nnz_factor", f.nnz_factor},
                   {"factor_flops", f.flops},
                   {"assembly_seconds", r.assembly_seconds},
                   {"analysis_seconds", f.analyze_seconds},
                   {"factorization_seconds", f.factor_seconds},
                   {"solve_seconds", r.solve_seconds},
                   {"peak_memory_bytes", r.peak_memory_bytes},
                   {"elements_per_rank", r.elements_per_rank},
                   {"relative_tolerance", r.solve.relative_tolerance},
                   {"iterations", r.solve.iterations},
                   {"relative_residuals", r.solve.relative_residual}};
  }
  if (!r.modes.empty()) {  // LinkStiffnessOptions::modes: the clamped link's natural frequencies
    json modes = json::array();
    for (size_t k = 0; k < r.modes.size(); ++k) {
      const fea::LinkMode& m = r.modes[k];
      modes.push_back({{"mode", k + 1},
                       {"frequency", m.frequency},
                       {"omega", m.omega},
                       {"residual", m.residual},
                       {"participation", to_array(m.participation)},
                       {"effective_mass", to_array(m.effective_mass)},
                       {"reference_motion", to_array(m.reference_motion)}});
    }
    j["vibration"] = {{"units",
                       {{"frequency", "Hz"},
                        {"omega", "rad/s"},
                        {"link_mass", "kg"},
                        {"participation", "sqrt(kg)"},
                        {"effective_mass", "kg"},
                        {"reference_motion", "m/sqrt(kg) (ux uy uz), rad/sqrt(kg) (rx ry rz)"}}},
                      {"mass_matrix", "consistent"},
                      {"reference_body_mass", 0.0},
                      {"link_mass", r.mass},
                      {"eigensolver_seconds", r.modes_seconds},
                      {"modes", modes}};
  }
  encode_non_finite(j);
  return j;
}

json convergence_study_to_json(const fea::ConvergenceStudy& study) {
  json meshes = json::array();
  for (std::size_t i = 0; i < study.sizes.size(); ++i)
    meshes.push_back({{"size_m", study.sizes[i]},
                      {"dofs", i < study.num_dofs.size() ? study.num_dofs[i] : 0},
                      {"compliance_diagonal",
                       i < study.compliance.size() ? to_array(study.compliance[i].diagonal()) : json::array()}});
  json estimates = json::array();
  for (std::size_t k = 0; k < study.diagonal.size(); ++k) {
    const auto& e = study.diagonal[k];
    json d = {{"dof", dof_name(static_cast<int>(k))}, {"status", status_json(e.status())}};
    if (e.ok())
      d.update({{"extrapolated", e->extrapolated}, {"order", e->order}, {"finest_relative_error", e->finest_error}});
    estimates.push_back(d);
  }
  json j = {{"compliance_diagonal_units", {"m/N", "m/N", "m/N", "rad/(N m)", "rad/(N m)", "rad/(N m)"}},
            {"meshes", meshes},
            {"richardson", estimates}};
  encode_non_finite(j);
  return j;
}

}  // namespace kinestat::io
