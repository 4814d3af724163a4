#include "kinestat/io/results_json.hpp"

#include "io/json_values.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "kinestat/core/atomic_file.hpp"

namespace kinestat::io {
namespace {

using nlohmann::json;

constexpr const char* kEndForceNames[6] = {"N", "Vy", "Vz", "T", "My", "Mz"};
constexpr const char* kStationNames[12] = {"N", "Vy", "Vz", "T", "My", "Mz", "ux", "uy", "uz", "rx", "ry", "rz"};

// Id of item i of `items`, or "#i" when the solution refers past the structure (never expected).
template <class T>
std::string id_of(const std::vector<T>& items, std::size_t i) {
  return i < items.size() ? items[i].id : fmt::format("#{}", i);
}

// Id of node n, or null for "no node" (-1).
json node_id(const msa::Structure& s, int n) {
  return n >= 0 ? json(id_of(s.nodes(), static_cast<std::size_t>(n))) : json();
}

json node_motion(const std::string& node, const Vec6& v) {
  return {{"node", node}, {"translation", to_array(v.head<3>())}, {"rotation", to_array(v.tail<3>())}};
}

// {"<key>": id, "force": [3], "moment": [3]}.
json wrench(const char* key, const std::string& id, const Vec6& w) {
  return {{key, id}, {"force", to_array(w.head<3>())}, {"moment", to_array(w.tail<3>())}};
}

json load_case_json(const msa::Structure& s, const msa::LoadCaseResult& r) {
  json c;
  c["name"] = r.name;
  c["max_translation"] = {{"node", node_id(s, r.max_translation_node)}, {"value", r.max_translation}};
  c["equilibrium"] = {{"resultant_force", to_array(r.resultant.head<3>())},
                      {"resultant_moment", to_array(r.resultant.tail<3>())},
                      {"error", r.equilibrium_error},
                      {"free_dof_residual", r.free_dof_residual}};
  c["displacements"] = json::array();
  for (std::size_t i = 0; i < r.displacement.size(); ++i)
    c["displacements"].push_back(node_motion(id_of(s.nodes(), i), r.displacement[i]));

  // Reactions exist at supported nodes only; each node once, in node order.
  std::vector<bool> supported(s.nodes().size(), false);
  for (const auto& sup : s.supports()) supported[static_cast<std::size_t>(sup.node)] = true;
  c["reactions"] = json::array();
  for (std::size_t i = 0; i < r.reaction.size() && i < supported.size(); ++i) {
    if (supported[i]) c["reactions"].push_back(wrench("node", s.nodes()[i].id, r.reaction[i]));
  }
  c["beam_end_forces"] = json::array();
  for (std::size_t i = 0; i < r.beam_end_forces.size(); ++i) {
    json b = {{"beam", id_of(s.beams(), i)}};
    for (int end = 0; end < 2; ++end) {
      json e;
      for (int k = 0; k < 6; ++k) e[kEndForceNames[k]] = r.beam_end_forces[i](6 * end + k);
      b[end == 0 ? "end1" : "end2"] = e;
    }
    c["beam_end_forces"].push_back(b);
  }
  c["joint_forces"] = json::array();
  for (std::size_t i = 0; i < r.joint_forces.size(); ++i) {
    c["joint_forces"].push_back(wrench("joint", id_of(s.joints(), i), r.joint_forces[i]));
  }
  return c;
}

// One beam's stations: x, each quantity as an array, and its extremes.
json stations_json(const std::string& beam, const msa::BeamStations& st) {
  json b = {{"beam", beam}, {"x", st.x}};
  for (int q = 0; q < 12; ++q) {
    json values = json::array();
    for (std::size_t k = 0; k < st.x.size(); ++k) values.push_back(q < 6 ? st.forces[k](q) : st.displacement[k](q - 6));
    b[kStationNames[q]] = values;
    const auto& e = st.extremes[static_cast<std::size_t>(q)];
    b["extremes"][kStationNames[q]] = {
        {"max", e.max}, {"x_at_max", e.x_at_max}, {"min", e.min}, {"x_at_min", e.x_at_min}};
  }
  return b;
}

json cartesian_json(const msa::Structure& s, const CartesianStiffness& cs) {
  json c;
  c["node"] = node_id(s, s.report_node().value_or(-1));  // Solution::cartesian is the report node's
  c["axes"] = "global";
  c["order"] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  c["compliance"] = to_rows(cs.compliance);
  c["compliance_units"] = unit_matrix(true);
  c["stiffness_defined"] = cs.stiffness_defined;
  c["stiffness"] = cs.stiffness_defined ? to_rows(cs.stiffness) : json();
  c["stiffness_units"] = unit_matrix(false);
  c["note"] = cs.note;
  c["indices"] = cs.indices ? stiffness_indices_to_json(*cs.indices) : json();
  return c;
}

json singularity_json(const msa::Structure& s, const msa::SingularityDiagnosis& d) {
  json j;
  j["singular"] = d.singular;
  j["message"] = d.message;
  j["weak_dofs"] = json::array();
  for (const auto& w : d.weak_dofs) {
    j["weak_dofs"].push_back({{"node", node_id(s, w.node)}, {"dof", dof_name(w.dof)}});
  }
  j["free_motions"] = json::array();
  for (const auto& m : d.modes) {
    json nodes = json::array();
    for (std::size_t i = 0; i < m.node_motion.size(); ++i)
      nodes.push_back(node_motion(id_of(s.nodes(), i), m.node_motion[i]));
    j["free_motions"].push_back(
        {{"rayleigh_ratio", m.rayleigh_ratio}, {"description", m.description}, {"nodes", nodes}});
  }
  return j;
}

void collect_non_finite(json& j, const json::json_pointer& at, json& notes) {
  if (j.is_number_float()) {
    const double x = j.get<double>();
    if (!std::isfinite(x)) {
      notes.push_back({{"path", at.to_string()}, {"value", std::isnan(x) ? "nan" : (x > 0 ? "inf" : "-inf")}});
      j = nullptr;
    }
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) collect_non_finite(j[i], at / i, notes);
  } else if (j.is_object()) {
    for (auto& [key, value] : j.items()) collect_non_finite(value, at / key, notes);
  }
}

}  // namespace

json stiffness_indices_to_json(const StiffnessIndices& ind) {
  json eigenvectors = json::array();
  for (Eigen::Index c = 0; c < ind.eigenvectors.cols(); ++c) eigenvectors.push_back(to_array(ind.eigenvectors.col(c)));
  return {{"size", ind.size},
          {"det_sign", ind.det_sign},
          {"log10_abs_det", ind.log10_abs_det},
          {"determinant", ind.determinant},
          {"trace", ind.trace},
          {"norm_1", ind.norm_1},
          {"norm_2", ind.norm_2},
          {"norm_frobenius", ind.norm_frobenius},
          {"norm_inf", ind.norm_inf},
          {"max_abs_entry", ind.max_abs_entry},
          {"condition_number", ind.condition_number},
          {"eigenvalues", to_array(ind.eigenvalues)},
          {"eigenvectors", eigenvectors},
          {"symmetry_error", ind.symmetry_error}};
}

void encode_non_finite(json& j) {
  json notes = json::array();
  collect_non_finite(j, json::json_pointer(), notes);
  if (!j.is_object()) return;
  json& all = j["non_finite_values"];
  if (!all.is_array()) all = json::array();
  for (auto& n : notes) all.push_back(std::move(n));
}

StatusOr<json> solution_to_json(const msa::Structure& s, const msa::Solution& sol,
                                const std::vector<std::vector<msa::BeamStations>>* stations) {
  if (Status st = msa::check_solution_matches(s, sol); !st.ok()) return st;
  json j;
  j["schema"] = "kinestat-msa-results";
  j["schema_version"] = kResultsSchemaVersion;
  j["units"] = {{"length", "m"}, {"force", "N"}, {"moment", "N m"}, {"angle", "rad"}, {"time", "s"}};
  j["model"] = {{"title", s.title()},
                {"num_nodes", s.nodes().size()},
                {"num_beams", s.beams().size()},
                {"num_joints", s.joints().size()},
                {"num_rigid_links", s.rigid_links().size()},
                {"num_supports", s.supports().size()},
                {"num_load_cases", s.load_cases().size()},
                {"num_dofs", sol.num_dofs},
                {"num_free_dofs", sol.num_free_dofs},
                {"report_node", node_id(s, s.report_node().value_or(-1))}};
  j["status"] = status_json(sol.status);
  j["regularized"] = sol.regularized;
  if (sol.second_order)
    j["analysis"] = {{"order", "second"},
                     {"method", "P-Delta: (K + K_G(N)) u = F iterated on the beams' axial forces N"},
                     {"tolerance", sol.second_order->tolerance},
                     {"max_iterations", sol.second_order->max_iterations}};
  else
    j["analysis"] = {{"order", "first"}, {"method", "linear: K u = F"}};

  const auto& f = sol.factorization;
  j["solver"] = {{"backend", sol.backend},
                 {"assembly_seconds", sol.assembly_seconds},
                 {"solve_seconds", sol.solve_seconds},
                 {"softest_mode_ratio", sol.softest_mode_ratio},
                 {"factorization",
                  {{"n", f.n},
                   {"nnz_matrix", f.nnz_matrix},
                   {"nnz_factor", f.nnz_factor},
                   {"flops", f.flops},
                   {"reused_symbolic", f.reused_symbolic},
                   {"supernodal", f.supernodal},
                   {"ordering", f.ordering},
                   {"analyze_seconds", f.analyze_seconds},
                   {"factor_seconds", f.factor_seconds},
                   {"failed_column", f.failed_column},
                   {"weak_columns", f.weak_columns},
                   {"min_pivot_ratio", f.min_pivot_ratio},
                   {"min_pivot_column", f.min_pivot_column}}}};

  j["load_cases"] = json::array();
  for (std::size_t c = 0; c < sol.cases.size(); ++c) {
    json lc = load_case_json(s, sol.cases[c]);
    if (sol.second_order) {
      const msa::SecondOrderReport& so = *sol.second_order;
      json N = json::array();
      for (std::size_t b = 0; b < s.beams().size(); ++b)
        N.push_back({{"beam", id_of(s.beams(), b)}, {"N", so.axial_force[c][b]}});
      lc["second_order"] = {
          {"iterations", so.iterations[c]}, {"relative_change", so.relative_change[c]}, {"axial_force", std::move(N)}};
    }
    if (stations && c < stations->size()) {
      lc["beam_stations"] = json::array();
      for (std::size_t b = 0; b < (*stations)[c].size(); ++b)
        lc["beam_stations"].push_back(stations_json(id_of(s.beams(), b), (*stations)[c][b]));
    }
    j["load_cases"].push_back(lc);
  }
  j["cartesian_stiffness"] = sol.cartesian ? cartesian_json(s, *sol.cartesian) : json();
  j["global_indices"] = sol.global_indices ? stiffness_indices_to_json(*sol.global_indices) : json();
  j["singularity"] = singularity_json(s, sol.singularity);
  encode_non_finite(j);
  return j;
}

StatusOr<json> buckling_to_json(const msa::Structure& s, const msa::BucklingResult& r) {
  if (r.axial_force.size() != s.beams().size())
    return Status::Invalid(fmt::format("buckling result: {} axial forces for a structure of {} beams",
                                       r.axial_force.size(), s.beams().size()));
  json j;
  j["schema"] = "kinestat-buckling-results";
  j["schema_version"] = kResultsSchemaVersion;
  j["units"] = {{"length", "m"}, {"force", "N"}, {"angle", "rad"}, {"load_factor", "-"}};
  j["model"] = {{"title", s.title()},
                {"num_nodes", s.nodes().size()},
                {"num_beams", s.beams().size()},
                {"num_free_dofs", r.num_free_dofs}};
  j["status"] = status_json(r.status);
  j["load_case"] = r.load_case_name;
  j["axial_forces"] = json::array();
  int most = -1;  // the most compressed beam
  for (std::size_t i = 0; i < r.axial_force.size(); ++i) {
    j["axial_forces"].push_back({{"beam", s.beams()[i].id}, {"N", r.axial_force[i]}});
    if (most < 0 || r.axial_force[i] < r.axial_force[static_cast<std::size_t>(most)]) most = static_cast<int>(i);
  }
  j["modes"] = json::array();
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const msa::BucklingMode& m = r.modes[k];
    if (m.shape.size() != s.nodes().size())
      return Status::Invalid(fmt::format("buckling mode {}: {} node motions for a structure of {} nodes", k + 1,
                                         m.shape.size(), s.nodes().size()));
    json mode = {{"mode", k + 1}, {"load_factor", m.load_factor}, {"residual", m.residual}};
    mode["most_compressed_beam"] = {
        {"beam", s.beams()[static_cast<std::size_t>(most)].id},
        {"critical_axial_force", m.load_factor * r.axial_force[static_cast<std::size_t>(most)]}};
    mode["shape"] = json::array();
    for (std::size_t n = 0; n < m.shape.size(); ++n) mode["shape"].push_back(node_motion(s.nodes()[n].id, m.shape[n]));
    j["modes"].push_back(std::move(mode));
  }
  encode_non_finite(j);
  return j;
}

StatusOr<json> modes_to_json(const msa::Structure& s, const msa::ModalResult& r, bool lumped) {
  json j;
  j["schema"] = "kinestat-modes-results";
  j["schema_version"] = kResultsSchemaVersion;
  j["units"] = {{"length", "m"},
                {"mass", "kg"},
                {"angle", "rad"},
                {"frequency", "Hz"},
                {"angular_frequency", "rad/s"},
                {"shape", "m/sqrt(kg) (translation), rad/sqrt(kg) (rotation)"},
                {"participation", "sqrt(kg)"}};
  j["model"] = {{"title", s.title()},
                {"num_nodes", s.nodes().size()},
                {"num_beams", s.beams().size()},
                {"num_free_dofs", r.num_free_dofs}};
  j["status"] = status_json(r.status);
  j["mass_matrix"] = lumped ? "lumped" : "consistent";
  // The stiffness the frequencies are of: the unstressed K (null) or K + K_G of a load case's axial forces.
  j["prestress"] = nullptr;
  if (r.prestress) {
    const msa::ModalPrestressReport& p = *r.prestress;
    if (p.axial_force.size() != s.beams().size())
      return Status::Invalid(fmt::format("modal result: {} prestress axial forces for a structure of {} beams",
                                         p.axial_force.size(), s.beams().size()));
    json pre = {{"load_case", p.load_case_name}, {"load_case_index", p.load_case}, {"second_order", p.second_order}};
    pre["axial_forces"] = json::array();
    for (std::size_t i = 0; i < p.axial_force.size(); ++i)
      pre["axial_forces"].push_back({{"beam", s.beams()[i].id}, {"N", p.axial_force[i]}});
    j["prestress"] = std::move(pre);
  }
  j["total_mass"] = to_array(r.total_mass);
  j["modes"] = json::array();
  for (std::size_t k = 0; k < r.modes.size(); ++k) {
    const msa::VibrationMode& m = r.modes[k];
    if (m.shape.size() != s.nodes().size())
      return Status::Invalid(
          fmt::format("mode {}: {} node motions for a structure of {} nodes", k + 1, m.shape.size(), s.nodes().size()));
    json mode = {{"mode", k + 1},
                 {"frequency", m.frequency},
                 {"omega", m.omega},
                 {"residual", m.residual},
                 {"participation", to_array(m.participation)},
                 {"effective_mass", to_array(m.effective_mass)}};
    mode["shape"] = json::array();
    for (std::size_t n = 0; n < m.shape.size(); ++n) mode["shape"].push_back(node_motion(s.nodes()[n].id, m.shape[n]));
    j["modes"].push_back(std::move(mode));
  }
  encode_non_finite(j);
  return j;
}

void write_json(std::ostream& out, const json& j, int indent) {
  // `replace`: a title with invalid UTF-8 must not abort the whole report.
  out << j.dump(indent, ' ', false, json::error_handler_t::replace) << '\n';
}

Status write_json(const std::string& path, const json& j, int indent) {
  std::ostringstream text;
  write_json(text, j, indent);
  return write_text_file_atomically(path, text.str());
}

}  // namespace kinestat::io
