#include "kinestat/fea/mesh_convergence.hpp"

#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"

namespace kinestat::fea {

StatusOr<RichardsonEstimate> richardson_estimate(const std::vector<double>& h, const std::vector<double>& f) {
  const size_t n = h.size();
  if (n < 3 || f.size() != n) return Status::Invalid("Richardson estimate: need three or more (size, value) pairs");
  for (size_t i = 1; i < n; ++i)
    if (!(h[i] < h[i - 1] && h[i] > 0.0))
      return Status::Invalid("Richardson estimate: mesh sizes must be positive and strictly decreasing");
  const double h1 = h[n - 3], h2 = h[n - 2], h3 = h[n - 1];
  const double d12 = f[n - 3] - f[n - 2], d23 = f[n - 2] - f[n - 1];
  if (!(d12 * d23 > 0.0))
    return Status::NotConverged(
        "Richardson estimate: the differences between meshes change sign or vanish; refine further");
  // Solve (h1^p - h2^p) / (h2^p - h3^p) = d12 / d23 for p by bisection on log(ratio), which
  // increases monotonically with p.
  const double target = std::log(d12 / d23);
  auto g = [&](double p) {
    return std::log((std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p)));
  };
  double lo = 1e-3, hi = 20.0;
  if (target <= g(lo) || target >= g(hi))
    return Status::NotConverged(fmt::format("Richardson estimate: no order in [{:g}, {:g}] fits", lo, hi));
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < target ? lo : hi) = mid;
  }
  RichardsonEstimate r;
  r.order = 0.5 * (lo + hi);
  const double c = d23 / (std::pow(h2, r.order) - std::pow(h3, r.order));
  r.extrapolated = f[n - 1] - c * std::pow(h3, r.order);
  r.finest_error = (f[n - 1] - r.extrapolated) / r.extrapolated;
  return r;
}

StatusOr<ConvergenceStudy> mesh_convergence_study(const std::function<StatusOr<TetMesh>(double h)>& make_mesh,
                                                  const std::vector<double>& sizes, const Material& material,
                                                  const LinkStiffnessOptions& options) {
  if (sizes.size() < 3) return Status::Invalid("mesh convergence study: give three or more mesh sizes");
  for (size_t i = 0; i < sizes.size(); ++i) {
    if (Status s = check_quantity(sizes[i], Quantity::kLength, fmt::format("sizes[{}]", i), {}, Sign::kPositive);
        !s.ok())
      return s;
    if (i > 0 && !(sizes[i] < sizes[i - 1]))
      return Status::Invalid(
          fmt::format("sizes[{}] = {:g} m after {:g} m: give the mesh sizes in strictly decreasing "
                      "order, coarse to fine (e.g. 0.004, 0.002, 0.001)",
                      i, sizes[i], sizes[i - 1]));
  }
  ConvergenceStudy study;
  study.sizes = sizes;
  LinkStiffnessOptions o = options;
  o.keep_fields = false;
  for (double h : sizes) {
    StatusOr<TetMesh> mesh = make_mesh(h);
    if (!mesh.ok()) return mesh.status();
    StatusOr<LinkStiffness> r = link_stiffness(*mesh, material, o);
    if (!r.ok()) return r.status();
    study.num_dofs.push_back(r->num_dofs);
    study.compliance.push_back(r->cartesian.compliance);
  }
  for (int k = 0; k < 6; ++k) {
    std::vector<double> f;
    for (const Mat6& C : study.compliance) f.push_back(C(k, k));
    study.diagonal.push_back(richardson_estimate(sizes, f));
  }
  return study;
}

std::string convergence_report(const ConvergenceStudy& s) {
  std::ostringstream os;
  os << "Mesh convergence of the compliance diagonal [m/N for ux uy uz, rad/(N m) for rx ry rz]\n";
  os << fmt::format("  {:>10} {:>9}", "size [m]", "dofs");
  for (int k = 0; k < 6; ++k) os << fmt::format(" {:>12}", dof_name(k));
  os << "\n";
  for (size_t i = 0; i < s.sizes.size(); ++i) {
    os << fmt::format("  {:10.4g} {:9d}", s.sizes[i], s.num_dofs[i]);
    for (int k = 0; k < 6; ++k) os << fmt::format(" {:12.5e}", s.compliance[i](k, k));
    os << "\n";
  }
  auto row = [&](const char* title, auto value) {
    os << fmt::format("  {:>20}", title);
    for (int k = 0; k < 6; ++k)
      os << (s.diagonal[k].ok() ? fmt::format(" {:12.5g}", value(*s.diagonal[k])) : fmt::format(" {:>12}", "n/a"));
    os << "\n";
  };
  // Always available, also where the meshes (CGAL's are not nested) are not yet in the asymptotic
  // range and Richardson says n/a: the relative change between the two finest meshes.
  const size_t n = s.sizes.size();
  os << fmt::format("  {:>20}", "change, last 2 meshes");
  for (int k = 0; k < 6; ++k)
    os << fmt::format(" {:12.3e}", (s.compliance[n - 1](k, k) - s.compliance[n - 2](k, k)) / s.compliance[n - 1](k, k));
  os << "\n";
  row("extrapolated", [](const RichardsonEstimate& r) { return r.extrapolated; });
  row("observed order", [](const RichardsonEstimate& r) { return r.order; });
  row("finest rel. error", [](const RichardsonEstimate& r) { return r.finest_error; });
  return os.str();
}

}  // namespace kinestat::fea
