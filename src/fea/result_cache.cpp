#include "kinestat/fea/result_cache.hpp"

#include <filesystem>
#include <fstream>
#include <limits>

#include <fmt/format.h>

namespace kinestat::fea {

namespace {

constexpr const char* kHeader = "kinestat-link-stiffness-cache 1";

std::string region_text(const Region& r) {
  return fmt::format("{} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} "
                     "{:.17g} {:.17g}",
                     static_cast<int>(r.kind), r.point.x(), r.point.y(), r.point.z(), r.normal.x(), r.normal.y(),
                     r.normal.z(), r.lo.x(), r.lo.y(), r.lo.z(), r.hi.x(), r.hi.y(), r.hi.z(), r.tolerance);
}

}  // namespace

std::string link_stiffness_cache_path(const std::string& dir, const std::string& key) {
  return (std::filesystem::path(dir) / (key + ".txt")).string();
}

std::uint64_t fnv1a(std::string_view data, std::uint64_t seed) {
  for (unsigned char c : data) seed = (seed ^ c) * 1099511628211ull;
  return seed;
}

std::string link_stiffness_cache_key(std::string_view mesh_identity, const Material& m, const LinkStiffnessOptions& o) {
  const Vec3 p = o.reference_point.value_or(Vec3::Constant(std::numeric_limits<double>::quiet_NaN()));
  std::string values = fmt::format(
      "{}|E {:.17g} G {:.17g}|clamp {}|reference {}|model {} ratio {:.17g}|point {} {:.17g} {:.17g} {:.17g}|"
      "ordering {} pivot {:.17g}",
      kHeader, m.E, m.G, region_text(o.clamp), region_text(o.reference), static_cast<int>(o.reference_model),
      o.stiff_body_ratio, o.reference_point.has_value(), p.x(), p.y(), p.z(), static_cast<int>(o.cholesky.ordering),
      o.cholesky.singular_pivot_ratio);
  // An iterative result is only as accurate as its tolerance: not interchangeable with a direct one.
  if (o.cholesky.backend == solver::Backend::kPetscCg)
    values += fmt::format("|cg rtol {:.17g}", o.cholesky.relative_tolerance);
  return fmt::format("{:016x}", fnv1a(values, fnv1a(mesh_identity)));
}

std::optional<LinkStiffness> load_cached_link_stiffness(const std::string& dir, const std::string& key) {
  std::ifstream in(link_stiffness_cache_path(dir, key));
  std::string header, stored_key;
  if (!in || !std::getline(in, header) || header != kHeader || !(in >> stored_key) || stored_key != key)
    return std::nullopt;
  LinkStiffness r;
  int model = 0;
  in >> model >> r.num_nodes >> r.num_elements >> r.nodes_per_element >> r.num_dofs;
  r.reference_model = static_cast<ReferenceModel>(model);
  Vec3 point;
  for (int i = 0; i < 3; ++i) in >> point(i);
  Mat6 C;
  for (int i = 0; i < 36; ++i) in >> C(i / 6, i % 6);
  if (!in) return std::nullopt;
  set_compliance(r, C, point);
  return r;
}

Status store_cached_link_stiffness(const std::string& dir, const std::string& key, const LinkStiffness& r) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  std::ofstream out(link_stiffness_cache_path(dir, key));
  if (ec || !out) return Status::Invalid(dir + ": cannot write the link stiffness cache there");
  out << kHeader << "\n" << key << "\n";
  out << fmt::format("{} {} {} {} {}\n", static_cast<int>(r.reference_model), r.num_nodes, r.num_elements,
                     r.nodes_per_element, r.num_dofs);
  const Vec3& p = r.cartesian.point;
  const Mat6& C = r.cartesian.compliance;
  out << fmt::format("{:.17g} {:.17g} {:.17g}\n", p.x(), p.y(), p.z());
  for (int i = 0; i < 6; ++i)
    out << fmt::format("{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", C(i, 0), C(i, 1), C(i, 2), C(i, 3), C(i, 4),
                       C(i, 5));
  return out ? Status::Ok() : Status::Internal(dir + ": writing the link stiffness cache failed");
}

}  // namespace kinestat::fea
