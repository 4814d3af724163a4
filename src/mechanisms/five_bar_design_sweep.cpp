#include "kinestat/mechanisms/five_bar_design_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/threads.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr int kMaxSteps = 1000;

Status check_range(const MapRange& r, const char* name) {
  if (!(std::isfinite(r.lo) && std::isfinite(r.hi) && r.lo > 0.0))
    return Status::Invalid(
        fmt::format("the {} range {:g}:{:g} m: link lengths must be positive and finite", name, r.lo, r.hi));
  if (r.lo > r.hi)
    return Status::Invalid(
        fmt::format("the {} range {:g}:{:g} m is reversed; write the smaller bound first", name, r.lo, r.hi));
  return Status::Ok();
}

}  // namespace

bool better_design(const FiveBarDesignResult& a, const FiveBarDesignResult& b) {
  if (a.stiff != b.stiff) return a.stiff > b.stiff;
  const auto key = [](double w) { return std::isnan(w) ? -std::numeric_limits<double>::infinity() : w; };
  return key(a.k_t_min_worst) > key(b.k_t_min_worst);
}

StatusOr<FiveBarDesignSweep> sweep_five_bar_designs(const FiveBarDesignSweepOptions& o) {
  if (Status s = check_range(o.r1, "r1"); !s.ok()) return s;
  if (Status s = check_range(o.r2, "r2"); !s.ok()) return s;
  const bool vary1 = o.r1.hi > o.r1.lo, vary2 = o.r2.hi > o.r2.lo;
  if ((vary1 || vary2) && (o.steps < 2 || o.steps > kMaxSteps))
    return Status::Invalid(
        fmt::format("{} designs per length: a range needs 2 to {} (a single value needs none)", o.steps, kMaxSteps));
  // The default MapGrid is one point: a sweep over it would rank designs by that point alone.
  const std::size_t n_region = o.region.num_points();
  if (o.region.num_varying_axes() < 2)
    return Status::Invalid(
        fmt::format("region: {} point(s), not a plane of P; set it to make_map_grid([(x0, x1), "
                    "(y0, y1), 0], step) (m), as `kinestat design fivebar --region`",
                    n_region));
  FiveBarKernelOptions first = o.base;  // r1, r2 are the swept ones: the ranges' first
  first.params.r1 = o.r1.lo;
  first.params.r2 = o.r2.lo;
  if (Status s = validate(first); !s.ok()) return s;
  MapOptions checked;  // the map options' fields the sweep sets, checked as a map checks them
  checked.near_singular_threshold = o.near_singular_threshold;
  checked.min_stiffness = o.min_stiffness;
  checked.threads = o.threads;
  if (Status s = validate(checked); !s.ok()) return s;

  FiveBarDesignSweep out;
  MapGrid& d = out.designs;
  d.origin = Vec3(o.r1.lo, o.r2.lo, 0.0);
  d.dimensions = {vary1 ? o.steps : 1, vary2 ? o.steps : 1, 1};
  const double s1 = vary1 ? (o.r1.hi - o.r1.lo) / (o.steps - 1) : 0.0;
  const double s2 = vary2 ? (o.r2.hi - o.r2.lo) / (o.steps - 1) : 0.0;
  // An axis of one design gets the other's spacing (or 1 mm): a grid's spacing is positive.
  d.spacing = Vec3(vary1 ? s1 : (vary2 ? s2 : 1e-3), vary2 ? s2 : (vary1 ? s1 : 1e-3), 1e-3);
  // Counted before anything runs: a sweep of hours is a choice to make, not a typo to start. The
  // time is estimated at 2.5e5 region points per second and thread (benchmarks/README.md).
  const double designs = static_cast<double>(d.dimensions[0]) * d.dimensions[1];
  const double postures = designs * static_cast<double>(n_region);
  const int threads = o.threads > 0 ? o.threads : available_cpus();
  const double hours = postures / (2.5e5 * threads) / 3600.0;
  if (Status s = check_size(
          postures, o.max_postures, fmt::format("{:g} designs x {} region points", designs, n_region), "postures",
          fmt::format("that is about {} on {} thread{}; sweep fewer designs (steps) or a coarser "
                      "region, or raise the limit (--max-postures, max_postures)",
                      hours >= 1 ? fmt::format("{:.2g} h", hours) : fmt::format("{:.2g} min", hours * 60.0), threads,
                      threads > 1 ? "s" : ""));
      !s.ok())
    return s;
  out.region = o.region;
  out.near_singular_threshold = o.near_singular_threshold;
  out.min_stiffness = o.min_stiffness;

  const auto make_kernel = o.make_kernel ? o.make_kernel : make_five_bar_kernel;
  MapOptions map_options;
  map_options.near_singular_threshold = o.near_singular_threshold;
  map_options.threads = o.threads;
  map_options.max_points = n_region;
  const std::size_t n_designs = d.num_points(), total = n_designs * n_region;
  out.results.reserve(n_designs);
  for (std::size_t k = 0; k < n_designs; ++k) {
    FiveBarKernelOptions design = o.base;
    design.params.r1 = d.point(k).x();
    design.params.r2 = d.point(k).y();
    const std::unique_ptr<PostureKernel> kernel = make_kernel(design);
    if (k == 0) out.description = kernel->description();
    if (o.progress)
      map_options.progress = [&, k](std::size_t done, std::size_t) { o.progress(k * n_region + done, total); };
    auto map = compute_workspace_map(*kernel, o.region, map_options);
    if (!map.ok()) return map.status();
    FiveBarDesignResult r{design.params.r1, design.params.r2};
    const std::vector<double>& k_t_min = map->find(MapField::kTranslationalMin)->values;
    double worst = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n_region; ++i) {
      const PostureStatus s = map->status[i];
      if (s == PostureStatus::kUnreachable) continue;
      ++r.reachable;
      if (s != PostureStatus::kOk) continue;
      ++r.singularity_free;
      worst = std::min(worst, k_t_min[i]);
      if (!o.min_stiffness || k_t_min[i] >= *o.min_stiffness) ++r.stiff;
    }
    if (r.singularity_free > 0) r.k_t_min_worst = worst;
    if (!out.results.empty() && better_design(r, out.results[out.best])) out.best = k;
    out.results.push_back(r);
  }
  return out;
}

}  // namespace kinestat::mechanisms
